#include "render/passes.h"

namespace bz::render {

// The picture (lines + HUD, after phosphor) plus bloom, tone-mapped and gamma-encoded into the
// target (the window or output image), optionally through Battlezone's colour overlay.
void pass_composite(const PassContext& ctx, const gl::Texture2D& picture, bool bloom, GLuint target_fbo,
                    int width, int height) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_fbo);
    glViewport(0, 0, width, height);
    gl::apply(gl::PipelineState{});
    const gl::Program& p = ctx.programs.composite;
    p.use();
    p.set("u_lines", 0);
    p.set("u_bloom", 1);
    p.set("u_bloom_strength", bloom ? ctx.settings.bloom_strength : 0.0f);
    p.set("u_exposure", ctx.settings.exposure);
    p.set("u_overlay", ctx.settings.beam.overlay ? 1 : 0);
    picture.bind(0);
    ctx.targets.bloom_out.bind(1);
    ctx.empty_vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace bz::render
