#include "render/passes.h"

namespace bz::render {

// Filled styles: the canvas is the picture; the HUD lines are laid over it in the style's
// HUD theme (shaders/styles/ink_composite.frag).
void pass_ink_composite(const PassContext& ctx) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ctx.target_fbo);
    glViewport(0, 0, ctx.targets.width, ctx.targets.height);
    gl::apply(gl::PipelineState{});
    const gl::Program& p = ctx.programs.ink_composite;
    p.use();
    // The style's HUD theme (scene::HudTheme): ink over a paper halo, or the beam's colours.
    const HudTheme& hud = ctx.style.hud;
    p.set("u_ink", hud.ink);
    p.set("u_ink_luminance", hud.ink_luminance);
    p.set("u_halo_px", hud.halo_px);
    p.set("u_paper", ctx.style.background);
    ctx.targets.canvas.bind(kTextureUnitCanvas);
    ctx.targets.lines.bind(kTextureUnitLines);
    ctx.empty_vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace bz::render
