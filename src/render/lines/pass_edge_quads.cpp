#include <cstddef>

#include "render/passes.h"

namespace bz::render {

namespace {

// The byte offset of a QuadDraw's command in the edge buffer's command buffer.
std::size_t command_offset(QuadDraw draw) {
    switch (draw) {
        case QuadDraw::sampled:
            return offsetof(EdgeDrawCommand, sampled_draw);
        case QuadDraw::tested:
            return offsetof(EdgeDrawCommand, tested_draw);
        case QuadDraw::every_record:
            break;
    }
    return 0;
}

}  // namespace

void draw_edge_record_quads(const PassContext& ctx, const gl::Program& program,
                            unsigned sample_capacity, QuadDraw draw) {
    // spine_visibility.comp's draws index the quads' corners (each corner's vertex shader runs
    // once); the append count itself is a count of unindexed vertices.
    const bool indexed = draw != QuadDraw::every_record;
    program.set("u_capacity", ctx.edges.capacity());
    program.set("u_sample_capacity", sample_capacity);
    program.set("u_indexed", indexed ? 1 : 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCommandBinding, ctx.edges.command().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, ctx.edges.records().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSamplesBinding, ctx.edges.samples().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSpansBinding, ctx.edges.spans().id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, ctx.edges.command().id());
    const auto* command = reinterpret_cast<const void*>(command_offset(draw));  // NOLINT
    if (indexed) {
        ctx.edges.quad_indices().bind();
        glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, command);
    } else {
        ctx.empty_vao.bind();
        glDrawArraysIndirect(GL_TRIANGLES, command);
    }
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

// The line pass of LineMethod::compute: one quad per edge-buffer record, drawn with the count
// the compute shader appended (glDrawArraysIndirect, no read-back), shaded by the same
// fragment stage as the geometry-shader path (spine test, beam).
//
// With spine samples, two draws, of which spine_visibility.comp gave one every record and
// the other none: the records' samples, or, when the frame asked for more samples than the
// buffer held, the spine test in every fragment. Two programs because llvmpipe runs both
// sides of a branch for every fragment: with the test compiled out, the seed's hallway's
// quads took 7.1 ms instead of 12.3 (800x600, render --repeat 10, min of 3).
void pass_edge_quads(const PassContext& ctx, bool mask_mode) {
    const bool levels = !mask_mode && dims_hidden_lines(ctx);
    const QuadPrograms& programs = mask_mode ? ctx.programs.edge_quads_mask
                                   : levels  ? ctx.programs.edge_quads_dim
                                             : ctx.programs.edge_quads;
    const bool sampled = wants_spine_samples(ctx);
    begin_line_target(ctx, programs.tested, mask_mode);
    if (levels) set_level_dim_uniforms(ctx, programs.tested);
    if (!sampled) {
        draw_edge_record_quads(ctx, programs.tested, 0u);
    } else {
        draw_edge_record_quads(ctx, programs.tested, ctx.edges.sample_capacity(), QuadDraw::tested);
        begin_line_target(ctx, programs.sampled, mask_mode, false);
        if (levels) set_level_dim_uniforms(ctx, programs.sampled);
        draw_edge_record_quads(ctx, programs.sampled, ctx.edges.sample_capacity(),
                               QuadDraw::sampled);
    }
    ctx.edges.keep_count();
}

}  // namespace bz::render
