#include "render/styles/stroke_common.h"

namespace bz::render {

// Toon and pop-art outlines (Castro & Macedo): ink quads over the fill, one per visible feature
// edge of the edge buffer, alpha-blended so their antialiased sides sit softly on the colour.
void pass_outline(const PassContext& ctx) {
    ctx.targets.canvas_fbo.bind();
    gl::PipelineState state;
    state.blend = gl::Blend::min;  // ink darkens; the order strokes land in does not matter
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    gl::apply(state);
    begin_strokes(ctx, ctx.programs.outline, StrokeVisibility::spine_test);
    draw_edge_strokes(ctx);
    ctx.edges.keep_count();
}

}  // namespace bz::render
