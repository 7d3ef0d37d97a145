#include <algorithm>

#include "render/clear_image.h"
#include "render/styles/stroke_common.h"

namespace bz::render {

namespace {

// Hidden lines (StyleDef::hidden, technical): up to which occlusion level they are drawn, and
// how: thinner and dashed, the dashes measured from the record's first end. Without the
// occlusion layers (a style that draws no hidden lines) none are drawn.
void set_hidden_line_uniforms(const PassContext& ctx, const gl::Program& p) {
    const scene::HiddenLines& h = ctx.style.hidden;
    const bool levels = style_needs_occlusion_levels(ctx.style) && ctx.occlusion;
    p.set("u_hidden_levels", levels ? std::clamp(h.levels, 0, kOcclusionLayers) : 0);
    p.set("u_hidden_width_scale", h.width_scale);
    p.set("u_dash_px", std::max(h.dash_px, 0.0f));
    p.set("u_gap_px", std::max(h.gap_px, 0.0f));
    if (levels) bind_occlusion_layers(ctx);
}

}  // namespace

// Toon and pop-art outlines (Castro & Macedo): ink quads over the fill, one per visible feature
// edge of the edge buffer, alpha-blended so their antialiased sides sit softly on the colour.
// The technical style adds the hidden edges, dashed, thinner and paler by occlusion level.
void pass_outline(const PassContext& ctx) {
    ctx.targets.canvas_fbo.bind();
    gl::PipelineState state;
    state.blend = gl::Blend::min;  // ink darkens; the order strokes land in does not matter
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    gl::apply(state);
    begin_strokes(ctx, ctx.programs.outline, StrokeVisibility::spine_test);
    set_hidden_line_uniforms(ctx, ctx.programs.outline);
    draw_edge_strokes(ctx);
    ctx.edges.keep_count();
}

void pass_outline_levels_mask(const PassContext& ctx) {
    ctx.targets.mask_fbo.bind();
    gl::PipelineState state;
    state.blend = gl::Blend::max;  // the lowest level (the brightest mark) wins
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    gl::apply(state);
    clear_colour(ctx, ctx.targets.mask, glm::vec4(0.0f));
    const gl::Program& p = ctx.programs.outline_levels_mask;
    begin_strokes(ctx, p, StrokeVisibility::spine_test);
    set_hidden_line_uniforms(ctx, p);
    draw_edge_strokes(ctx);
}

}  // namespace bz::render
