#include "render/clear_image.h"
#include "render/passes.h"

namespace bz::render {

// The picture (lines + HUD, after phosphor) plus bloom, tone-mapped and gamma-encoded into the
// target (the window or output image), optionally through Battlezone's colour overlay.
// With the list of lit tiles (pass_tiles) it is sparse: the target is cleared to black, which
// is what an unlit pixel composites to exactly, and only the listed tiles are shaded (one
// indirect draw); on llvmpipe a full-screen pass costs per pixel even where it writes black.
// Reads: the picture, Targets::bloom_out, sparse Targets::tile_list; with the phosphor
// FrameHistory::phosphor. Writes: the target; with the phosphor FrameHistory::phosphor (in
// place) and FrameHistory::picture_lit (cleared, then marked).
// With the phosphor it also updates the picture (phosphor.glsl) in place: each invocation loads
// its own pixel's texel and stores it only where the value changed, so there is no hazard
// between invocations and a dark or unchanged pixel costs no store.
void pass_composite(const PassContext& ctx, const gl::Texture2D& picture, bool bloom,
                    GLuint target_fbo, int width, int height, const PhosphorStep* phosphor) {
    const Targets& t = ctx.targets;
    // Sparse where this frame's list (or the held frame's) built the list of lit tiles.
    const bool sparse = bloom && t.lit_tiles && frame_wrote(ctx, Resource::tile_list) &&
                        ctx.settings.sparse_composite;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target_fbo);
    glViewport(0, 0, width, height);
    gl::apply(gl::PipelineState{});
    if (sparse) {
        // Black is what an unlit pixel composites to exactly. The window's framebuffer has no
        // image a compute shader could clear.
        if (target_fbo == t.output_fbo.id()) {
            clear_colour(ctx, t.output, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        } else {
            glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
        }
    }
    const Programs& programs = ctx.programs;
    const std::size_t decay = phosphor && phosphor->power_law ? 1 : 0;
    const gl::Program& p =
        sparse ? (phosphor ? programs.composite_tiles_phosphor[decay] : programs.composite_tiles)
               : (phosphor ? programs.composite_phosphor[decay] : programs.composite);
    p.use();
    p.set("u_bloom_strength", bloom ? ctx.settings.bloom_strength : 0.0f);
    p.set("u_exposure", ctx.settings.exposure);
    p.set("u_overlay", ctx.settings.beam.overlay ? 1 : 0);
    p.set("u_overlay_safe", ctx.settings.beam.colour_safe ? 1 : 0);
    p.set("u_inv_screen",
          glm::vec2(1.0f / static_cast<float>(width), 1.0f / static_cast<float>(height)));
    picture.bind(kTextureUnitLines);
    t.bloom_out.bind(kTextureUnitBloom);
    if (phosphor) {
        set_phosphor_uniforms(p, *phosphor);
        glBindImageTexture(kImageUnitPicture, ctx.history.phosphor.id(), 0, GL_FALSE, 0,
                           GL_READ_WRITE, GL_RGBA16F);
        // tile_list.comp has read last frame's marks; this frame's composite marks them afresh.
        const gl::Texture2D& lit = ctx.history.picture_lit;
        glClearTexImage(lit.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
        glBindImageTexture(kImageUnitPictureLit, lit.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
    }
    ctx.empty_vao.bind();
    if (!sparse) {
        glDrawArrays(GL_TRIANGLES, 0, 3);
    } else {
        draw_listed_tiles(p, t, glm::ivec2(width, height));
    }
    // The picture is loaded as an image next frame, shown as a texture by held frames and read
    // back by tests; its lit tiles are read as a texture by next frame's tile_list.comp.
    if (phosphor) {
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
}

}  // namespace bz::render
