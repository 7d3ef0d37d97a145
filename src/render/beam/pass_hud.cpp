#include <algorithm>

#include "render/beam/beam_uniforms.h"
#include "render/passes.h"

namespace bz::render {

namespace {

// The HUD's beam where it gets no glow (shaders/hud/hud.geom's u_hud_beam): at least 2.25 px
// wide on a 1080-line screen (1.5 px at 720), so that a thin radar line's pixel centres get
// the beam's core, and 1.5 times as bright, about what the bloom added on the text before.
// Measured with HudContrastTest at 1280x720: the worst tile's WCAG ratio went from 4.32
// (classic) and 4.44 (mame) with the width alone to 5.37 and 5.40; the ring 3-5 px from the
// text stays black.
glm::vec2 hud_beam_without_glow(int target_height) {
    constexpr float kLeastHalfWidth1080Px = 2.25f;
    constexpr float kGain = 1.5f;
    return {std::max(1.5f, kLeastHalfWidth1080Px * static_cast<float>(target_height) / 1080.0f),
            kGain};
}

}  // namespace

// HUD lines go into the same HDR target as the scene's lines, with the scene's beam profile
// (on the dark looks a little wider and brighter, hud_beam_without_glow).
// On the dark looks the pass runs after the bloom (frame_passes.cpp), so the HUD, the menus
// and the notices do not glow: a wide bloom (mame's chain spreads ~200 px) lifted the black
// around the text to a WCAG contrast of 2.8-4.0 and left a green haze behind menu lists.
// The composite reads the lines target, so the HUD is still shown (and kept by the phosphor);
// after a bloom its lit fragments mark the composite's lit tiles (Targets::lit_tiles, which
// the bloom has cleared and pass_tiles lists next), before one its quads mark the beam's
// screen tiles (read by the bloom's sparse first downsample).
// Reads and writes (frame_passes.cpp): Targets::lines; Targets::lit_tiles or Targets::beam_tiles
// (marks, only where an earlier pass of the frame cleared them).
void pass_hud(const PassContext& ctx) {
    if (ctx.hud_vertex_count == 0) return;
    Targets& t = ctx.targets;
    t.lines_fbo.bind();
    gl::PipelineState state;
    state.blend = ctx.settings.beam.blend == BeamBlend::additive ? gl::Blend::add : gl::Blend::max;
    gl::apply(state);
    // The ink theme's halo is in alpha (shaders/hud/hud.frag): the strongest line's, not a sum.
    if (ctx.style.hud.ink)
        glBlendEquationSeparate(state.blend == gl::Blend::add ? GL_FUNC_ADD : GL_MAX, GL_MAX);
    const bool after_bloom = ctx.picture && ctx.picture->bloom;
    const bool mark_lit = after_bloom && t.lit_tiles && ctx.settings.sparse_composite;
    const gl::Program& p = mark_lit ? ctx.programs.hud_lit_tiles : ctx.programs.hud;
    p.use();
    p.set("u_viewport", glm::vec2(static_cast<float>(t.width), static_cast<float>(t.height)));
    set_beam_uniforms(p, ctx.settings.beam, ctx.settings.line_half_width_px, t.height, ctx.seed,
                      false);
    // The glowing HUD theme (the dark looks) is drawn after the bloom, or without one
    // (RenderSettings::hud_glow: before it, as the scene's lines).
    const bool without_glow = !ctx.style.hud.ink && !ctx.settings.hud_glow;
    p.set("u_hud_beam", without_glow ? hud_beam_without_glow(t.height) : glm::vec2(0.0f, 1.0f));
    p.set("u_ink_halo_px", ctx.style.hud.ink ? std::max(ctx.style.hud.halo_px, 0.0f) : 0.0f);
    if (mark_lit) {
        bind_lit_tile_marks(p, t, true);
    } else if (frame_wrote(ctx, Resource::beam_tiles)) {
        // It adds its marks to the screen tiles an earlier pass of this frame cleared (the
        // line pass, a filled style's fill); else no image is bound and its stores do nothing.
        bind_beam_tiles(t);
        p.set("u_skip_beam_tiles", ctx.dense_first_downsample ? 1 : 0);
    } else {
        glBindImageTexture(kImageUnitBeamTiles, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
    }
    ctx.hud_vao.bind();
    glDrawArrays(GL_LINES, 0, ctx.hud_vertex_count);
}

}  // namespace bz::render
