#include "render/passes.h"

namespace bz::render {

// Which screen tiles the sparse composite shades (shaders/tiles.comp): those under lit
// picture blocks (marked by the bloom's first downsample) or under non-zero finished bloom.
// One invocation per tile; the composite reads the result in its vertex stage.
void pass_tiles(const PassContext& ctx) {
    Targets& t = ctx.targets;
    if (!t.tiles) return;
    const gl::Program& p = ctx.programs.tiles;
    p.use();
    p.set("u_occupancy", 0);
    p.set("u_bloom", 1);
    p.set("u_screen", glm::ivec2(t.width, t.height));
    t.lit.bind(0);
    t.bloom_out.bind(1);
    glBindImageTexture(0, t.tiles.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8UI);
    glDispatchCompute(static_cast<GLuint>((t.tiles.width() + 7) / 8), static_cast<GLuint>((t.tiles.height() + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    t.tiles_valid = true;
}

}  // namespace bz::render
