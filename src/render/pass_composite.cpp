#include "render/passes.h"

namespace bz::render {

// The picture (lines + HUD, after phosphor) plus bloom, tone-mapped and gamma-encoded into the
// target (the window or output image), optionally through Battlezone's colour overlay.
// With the bloom's lit tiles (pass_tiles) it is sparse: the target is cleared to black, which
// is what an unlit pixel composites to exactly, and only the lit tiles are shaded; on
// llvmpipe a full-screen pass costs per pixel even where it writes black.
void pass_composite(const PassContext& ctx, const gl::Texture2D& picture, bool bloom, GLuint target_fbo,
                    int width, int height) {
    const Targets& t = ctx.targets;
    const bool sparse = bloom && t.tiles_valid && ctx.settings.sparse_composite;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_fbo);
    glViewport(0, 0, width, height);
    gl::apply(gl::PipelineState{});
    const gl::Program& p = sparse ? ctx.programs.composite_tiles : ctx.programs.composite;
    p.use();
    p.set("u_lines", 0);
    p.set("u_bloom", 1);
    p.set("u_bloom_strength", bloom ? ctx.settings.bloom_strength : 0.0f);
    p.set("u_exposure", ctx.settings.exposure);
    p.set("u_overlay", ctx.settings.beam.overlay ? 1 : 0);
    p.set("u_inv_screen", glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)));
    picture.bind(0);
    t.bloom_out.bind(1);
    ctx.empty_vao.bind();
    if (!sparse) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
        return;
    }
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    p.set("u_tiles", 2);
    p.set("u_screen", glm::ivec2(width, height));
    t.tiles.bind(2);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, t.tiles.width() * t.tiles.height());
}

}  // namespace bz::render
