#include <algorithm>
#include <cmath>

#include "render/passes.h"

namespace bz::render {

namespace {

// How far past a HUD quad every tile that holds a pixel within that distance of it is already
// marked, in pixels: shaders/beam/beam_tiles.glsl marks, around points at most half a tile
// apart along the line, every tile within half_width + half a tile + 1 px, so a pixel within
// half_width + R of the line lies in a marked tile while R <= a quarter tile + 1 px.
constexpr float kMarkSlackPx = static_cast<float>(kScreenTileSize) / 4.0f + 1.0f;

// The screen tiles past the marked ones that the ink composite may change: the HUD pass
// writes its paper halo up to halo_px past each line's beam (shaders/hud/hud.frag). 0 for
// the usual halo of a few pixels; InkCompositeTilesTest holds the slack to what the marks give.
int halo_reach_tiles(const HudTheme& hud) {
    if (!hud.ink) return 0;
    const float past_marks_px = std::max(0.0f, hud.halo_px - kMarkSlackPx);
    return static_cast<int>(std::ceil(past_marks_px / static_cast<float>(kScreenTileSize)));
}

void set_theme_uniforms(const gl::Program& p, const PassContext& ctx) {
    // The style's HUD theme (scene::HudTheme): ink over a paper halo, or the beam's colours.
    const HudTheme& hud = ctx.style.hud;
    p.set("u_ink", hud.ink);
    p.set("u_ink_luminance", hud.ink_luminance);
    p.set("u_paper", ctx.style.background);
}

}  // namespace

// Filled styles: the canvas is the picture; the HUD lines are laid over it in the style's
// HUD theme (shaders/styles/ink_composite.frag). Where neither the HUD nor its halo reaches,
// that shader returns the canvas unchanged, and on llvmpipe it cost ~40 ms a frame at
// 1280x720 when run on every pixel with its halo's 16 taps (docs/measurements/styles-sweep.md). So
// the canvas is copied to the target whole (a blit), and the shader runs only over the screen tiles
// the HUD pass marked (Targets::beam_tiles, cleared by pass_fill; beam lines on a filled style mark
// theirs too, pass_lines), grown by the halo's reach past the marks' own slack.
// RenderSettings::sparse_composite off runs it on every pixel: the same picture, to compare.
void pass_ink_composite(const PassContext& ctx) {
    const int w = ctx.targets.width, h = ctx.targets.height;
    gl::apply(gl::PipelineState{});
    const bool sparse = ctx.settings.sparse_composite;
    if (sparse) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, ctx.targets.canvas_fbo.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ctx.target_fbo);
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ctx.target_fbo);
    glViewport(0, 0, w, h);
    const gl::Program& p = sparse ? ctx.programs.ink_composite_tiles : ctx.programs.ink_composite;
    p.use();
    set_theme_uniforms(p, ctx);
    ctx.targets.canvas.bind(kTextureUnitCanvas);
    ctx.targets.lines.bind(kTextureUnitLines);
    ctx.empty_vao.bind();
    if (!sparse) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        return;
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the HUD's marks were image stores
    p.set("u_reach", halo_reach_tiles(ctx.style.hud));
    draw_tile_quads(p, ctx.targets.beam_tiles, glm::ivec2(w, h));
}

}  // namespace bz::render
