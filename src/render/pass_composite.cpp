#include "render/passes.h"

namespace bz::render {

// Lines + bloom, tone-mapped and gamma-encoded into the target (the window or output image).
void pass_composite(const PassContext& ctx) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ctx.target_fbo);
    glViewport(0, 0, ctx.targets.width, ctx.targets.height);
    gl::apply(gl::PipelineState{});
    const gl::Program& p = ctx.programs.composite;
    p.use();
    p.set("u_lines", 0);
    p.set("u_bloom", 1);
    p.set("u_bloom_strength", ctx.settings.bloom_strength);
    p.set("u_exposure", ctx.settings.exposure);
    ctx.targets.lines.bind(0);
    ctx.targets.bloom_a.bind(1);
    ctx.empty_vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace bz::render
