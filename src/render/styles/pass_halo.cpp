#include "render/clear_image.h"
#include "render/styles/stroke_common.h"

namespace bz::render {

namespace {

gl::PipelineState halo_state(const PassContext& ctx, gl::Blend blend) {
    // Depth-tested against the shrunk-mesh mask, never written.
    gl::PipelineState state = depth_writing_state(ctx, true);
    state.depth_write = false;
    state.blend = blend;
    return state;
}

}  // namespace

// Haloed strokes (Loviscach), three steps:
//  1. the soft halo outside every visible silhouette into the off-screen halo buffer, MAX
//     blended (so the zig-zags of extracted silhouettes merge without seams);
//  2. the halo laid over the canvas: surfaces behind the stroke that cast it fade to paper;
//  3. the ink strokes, reaching inside and outside the silhouette, over the shrunk mask.
void pass_halo(const PassContext& ctx) {
    const HaloParams& h = ctx.style.halo;
    ctx.targets.halo_fbo.bind();
    gl::apply(halo_state(ctx, gl::Blend::max));
    clear_colour(ctx, ctx.targets.halo, glm::vec4(0.0f));
    const gl::Program& glow = ctx.programs.halo_glow;
    begin_strokes(ctx, glow, StrokeVisibility::depth_test);
    glow.set("u_strokes", h.strokes_per_edge);
    ctx.style_textures.profile.bind(kTextureUnitProfile);
    // Its quads mark the screen tiles they cover (beam_tiles.glsl), in the HUD's marks, which
    // start clean again below: on llvmpipe laying the halo over every pixel cost ~11 of the
    // pass's ~17 ms at 1280x720 (docs/measurements/styles-sweep.md).
    glClearTexImage(ctx.targets.beam_tiles.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    bind_beam_tiles(ctx.targets);
    draw_edge_strokes(ctx);

    ctx.targets.canvas_fbo.bind();
    gl::PipelineState apply_state;
    apply_state.blend = gl::Blend::alpha;
    gl::apply(apply_state);
    // The canvas stays opaque: the composite copies it to the target as it is.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    // Only where a halo quad was drawn (RenderSettings::sparse_composite off: every pixel,
    // the same picture).
    const bool sparse = ctx.settings.sparse_composite;
    const gl::Program& lay = sparse ? ctx.programs.halo_apply_tiles : ctx.programs.halo_apply;
    lay.use();
    set_spine_test_uniforms(lay, ctx);
    lay.set("u_paper", ctx.style.background);
    ctx.targets.depth.bind(kTextureUnitDepth);
    ctx.targets.halo.bind(kTextureUnitHalo);
    ctx.empty_vao.bind();
    if (sparse) {
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the marks were image stores
        lay.set("u_reach", 0);                          // the marks hold every pixel of the quads
        draw_tile_quads(lay, ctx.targets.beam_tiles,
                        glm::ivec2(ctx.targets.width, ctx.targets.height));
    } else {
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    // The HUD marks its own tiles there next (pass_ink_composite.cpp reads them).
    glClearTexImage(ctx.targets.beam_tiles.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);

    ctx.targets.canvas_shrunk_fbo.bind();
    gl::apply(halo_state(ctx, gl::Blend::min));
    const gl::Program& ink = ctx.programs.halo;
    begin_strokes(ctx, ink, StrokeVisibility::depth_test);
    ink.set("u_strokes", h.strokes_per_edge);
    ctx.style_textures.profile.bind(kTextureUnitProfile);
    ctx.style_textures.offset.bind(kTextureUnitOffset);
    ctx.targets.halo.bind(kTextureUnitHalo);
    draw_edge_strokes(ctx);
    ctx.edges.keep_count();
}

}  // namespace bz::render
