#include "render/clear_image.h"
#include "render/styles/stroke_common.h"

namespace bz::render {

// Pencil strokes over the paper (Olejnik & Litchmore), or in mask mode their centre lines.
void pass_sketch(const PassContext& ctx, bool mask_mode) {
    gl::PipelineState state;
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    if (mask_mode) {
        ctx.targets.mask_fbo.bind();
        state.blend = gl::Blend::max;
        gl::apply(state);
        clear_colour(ctx, ctx.targets.mask, glm::vec4(0.0f));
    } else {
        ctx.targets.canvas_fbo.bind();
        state.blend = gl::Blend::min;  // the darkest stroke wins: any order gives the same picture
        gl::apply(state);
    }
    const gl::Program& p = mask_mode ? ctx.programs.sketch_mask : ctx.programs.sketch;
    begin_strokes(ctx, p, StrokeVisibility::spine_test);
    const SketchParams& s = ctx.style.sketch;
    p.set("u_strokes", s.strokes_per_edge);
    p.set("u_darkness", s.darkness);
    p.set("u_min_significance", s.min_significance);
    ctx.style_textures.noise.bind(kTextureUnitNoise);
    draw_edge_strokes(ctx);
    ctx.edges.keep_count();
}

}  // namespace bz::render
