#include "render/passes.h"

namespace bz::render {

// Which screen tiles the sparse composite shades (shaders/beam/tiles.comp): those under lit
// picture blocks (marked by the bloom's first downsample) or under non-zero finished bloom.
// With the phosphor, also those where the picture held light last frame (Targets::picture_lit):
// the composite must decay them, and every other tile of the picture is exactly black.
// One invocation per tile; the composite reads the result in its vertex stage.
void draw_tile_quads(const gl::Program& program, const gl::Texture2D& tiles, glm::ivec2 screen,
                     int unit) {
    program.set("u_tiles", unit);
    program.set("u_screen", screen);
    tiles.bind(unit);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, tiles.width() * tiles.height());
}

void pass_tiles(const PassContext& ctx) {
    Targets& t = ctx.targets;
    if (!t.tiles) return;
    const PhosphorStep* phosphor =
        ctx.picture && ctx.picture->phosphor ? &*ctx.picture->phosphor : nullptr;
    const gl::Texture2D& tiles = t.tiles;
    const gl::Program& p = ctx.programs.tiles;
    p.use();
    p.set("u_occupancy", 0);
    p.set("u_bloom", 1);
    p.set("u_screen", glm::ivec2(t.width, t.height));
    p.set("u_phosphor", phosphor ? 1 : 0);
    p.set("u_picture_lit", 2);
    t.lit.bind(0);
    t.bloom_out.bind(1);
    if (phosphor) t.picture_lit.bind(2);
    glBindImageTexture(0, tiles.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
    glDispatchCompute(static_cast<GLuint>((tiles.width() + 7) / 8),
                      static_cast<GLuint>((tiles.height() + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    t.tiles_valid = true;
}

}  // namespace bz::render
