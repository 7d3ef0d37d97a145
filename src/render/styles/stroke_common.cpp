#include "render/styles/stroke_common.h"

namespace bz::render {

void begin_strokes(const PassContext& ctx, const gl::Program& p, StrokeVisibility visibility) {
    p.use();
    set_edge_projection_uniforms(p, ctx);
    if (visibility == StrokeVisibility::spine_test) set_spine_test_uniforms(p, ctx);
    p.set("u_capacity", ctx.edges.capacity());
    p.set("u_light_dir", glm::normalize(ctx.style.light_dir));
    const OutlineParams& o = ctx.style.outline;
    p.set("u_width_px",
          ctx.style.lines == LinePass::sketch ? ctx.style.sketch.width_px : o.width_px);
    p.set("u_overdraw", o.overdraw);
    p.set("u_one_sided",
          o.quad == OutlineQuad::one_sided || ctx.settings.one_sided_outlines ? 1 : 0);
    p.set("u_ink", o.ink);
    const SketchParams& s = ctx.style.sketch;
    p.set("u_jitter_px", s.jitter_px);
    const HaloParams& h = ctx.style.halo;
    p.set("u_inner_px", h.inner_px);
    p.set("u_outer_px", h.outer_px);
    p.set("u_halo_px", h.halo_px);
    p.set("u_smoothing", h.cubic_smoothing && ctx.settings.cubic_smoothing ? 1 : 0);
    ctx.targets.depth.bind(kTextureUnitDepth);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding, ctx.instances.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, ctx.edges.records().id());
}

void draw_edge_strokes(const PassContext& ctx) {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, ctx.edges.command().id());
    ctx.empty_vao.bind();
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace bz::render
