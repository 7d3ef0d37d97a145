#include "render/beam/beam_uniforms.h"
#include "render/passes.h"

namespace bz::render {

// HUD lines go into the same HDR target before bloom, so text and radar glow like the scene.
void pass_hud(const PassContext& ctx) {
    if (ctx.hud_vertex_count == 0) return;
    ctx.targets.lines_fbo.bind();
    gl::PipelineState state;
    state.blend = ctx.settings.beam.blend == BeamBlend::additive ? gl::Blend::add : gl::Blend::max;
    gl::apply(state);
    const gl::Program& p = ctx.programs.hud;
    p.use();
    p.set("u_viewport",
          glm::vec2(static_cast<float>(ctx.targets.width), static_cast<float>(ctx.targets.height)));
    set_beam_uniforms(p, ctx.settings.beam, ctx.settings.line_half_width_px, ctx.targets.height,
                      ctx.seed, false);
    // The HUD adds its marks to the beam's tiles where this frame's line pass made them; else
    // no image is bound and its stores do nothing (no tile list reads them).
    if (frame_wrote(ctx, Resource::beam_tiles)) {
        bind_beam_tiles(ctx.targets);
    } else {
        glBindImageTexture(kImageUnitBeamTiles, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
    }
    ctx.hud_vao.bind();
    glDrawArrays(GL_LINES, 0, ctx.hud_vertex_count);
}

}  // namespace bz::render
