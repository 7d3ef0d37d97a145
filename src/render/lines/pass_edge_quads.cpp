#include "render/passes.h"

namespace bz::render {

void draw_edge_record_quads(const PassContext& ctx, const gl::Program& program,
                            unsigned sample_capacity) {
    program.set("u_capacity", ctx.edges.capacity());
    program.set("u_sample_capacity", sample_capacity);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCommandBinding, ctx.edges.command().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, ctx.edges.records().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSamplesBinding, ctx.edges.samples().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSpansBinding, ctx.edges.spans().id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, ctx.edges.command().id());
    ctx.empty_vao.bind();
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

// The line pass of LineMethod::compute: one quad per edge-buffer record, drawn with the count
// the compute shader appended (glDrawArraysIndirect, no read-back), shaded by the same
// fragment stage as the geometry-shader path (spine test, beam).
void pass_edge_quads(const PassContext& ctx, bool mask_mode) {
    const bool levels = !mask_mode && dims_hidden_lines(ctx);
    const gl::Program& program = mask_mode ? ctx.programs.edge_quads_mask
                                 : levels  ? ctx.programs.edge_quads_dim
                                           : ctx.programs.edge_quads;
    begin_line_target(ctx, program, mask_mode);
    if (levels) set_level_dim_uniforms(ctx, program);
    draw_edge_record_quads(ctx, program, ctx.edges.sample_capacity());
    ctx.edges.keep_count();
}

}  // namespace bz::render
