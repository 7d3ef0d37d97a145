#include <algorithm>

#include "render/passes.h"

namespace bz::render {

namespace {

constexpr GLuint kGroupSize = 64;  // intersections.comp's local size

}  // namespace

// The records go where the edges pass's went: same buffers, same counters, so spine
// visibility and the quads draw them with the meshes' edges.
void append_intersections(const PassContext& ctx, bool samples) {
    if (ctx.intersection_count == 0 || !ctx.intersections) return;
    const gl::Program& program = ctx.programs.intersections;
    program.use();
    set_edge_projection_uniforms(program, ctx);
    program.set("u_count", ctx.intersection_count);
    program.set("u_capacity", ctx.edges.capacity());
    program.set("u_sample_capacity", samples ? ctx.edges.sample_capacity() : 0u);
    program.set("u_sample_margin", 16.0f);  // as the edges pass
    program.set("u_sample_spacing", ctx.settings.spine_sample_spacing_px);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIntersectionsBinding, ctx.intersections->id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, ctx.edges.records().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCommandBinding, ctx.edges.command().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSpansBinding, ctx.edges.spans().id());
    glDispatchCompute((ctx.intersection_count + kGroupSize - 1) / kGroupSize, 1, 1);
}

// The geometry shader draws the meshes' lines without the edge buffer; the intersection
// segments, which are no mesh's edges, fill it alone. The CPU knows their count, so the
// buffer is sized before the fill and no counter is read back. No spine samples: the quads'
// fragments run the spine test, as the geometry shader's do.
void pass_intersection_edges(const PassContext& ctx) {
    ctx.edges.reserve(ctx.intersection_count);
    ctx.edges.reset();
    append_intersections(ctx, false);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void pass_intersection_quads(const PassContext& ctx, bool mask_mode) {
    if (ctx.intersection_count == 0) return;
    const gl::Program& program =
        mask_mode ? ctx.programs.edge_quads_mask.tested : ctx.programs.edge_quads.tested;
    begin_line_target(ctx, program, mask_mode, false);
    draw_edge_record_quads(ctx, program, 0u);  // no spine samples: the fragments test
}

}  // namespace bz::render
