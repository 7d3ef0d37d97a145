#include "render/targets.h"

#include <algorithm>

namespace bz::render {

Targets make_targets(int width, int height, const RenderSettings& s) {
    Targets t;
    t.width = width;
    t.height = height;
    const GLenum depth_format =
        s.depth == DepthFormat::reversed_f32 ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24;
    t.depth = gl::Texture2D(width, height, depth_format, gl::Filter::nearest);
    t.lines = gl::Texture2D(width, height, GL_RGBA16F, gl::Filter::linear);
    const int f = static_cast<int>(s.bloom_resolution);
    const int bw = std::max(1, width / f), bh = std::max(1, height / f);
    t.bloom_a = gl::Texture2D(bw, bh, GL_RGBA16F, gl::Filter::linear);
    t.bloom_b = gl::Texture2D(bw, bh, GL_RGBA16F, gl::Filter::linear);
    t.bloom_out = gl::Texture2D(bw, bh, GL_RGBA8, gl::Filter::linear);
    const int tiles_x = (width + kScreenTileSize - 1) / kScreenTileSize;
    const int tiles_y = (height + kScreenTileSize - 1) / kScreenTileSize;
    const int lit_x = (width + kLitTileSize - 1) / kLitTileSize;
    const int lit_y = (height + kLitTileSize - 1) / kLitTileSize;
    if (width % f == 0 && height % f == 0) {
        t.lit_tiles = gl::Texture2D(lit_x, lit_y, GL_R8UI, gl::Filter::nearest);
        // The draw command (4 words), then one word per tile at most.
        const std::size_t words = 4 + static_cast<std::size_t>(lit_x) * lit_y;
        t.tile_list.set_data(nullptr, words * sizeof(GLuint), GL_DYNAMIC_DRAW);
    }
    t.beam_tiles = gl::Texture2D(tiles_x, tiles_y, GL_R8UI, gl::Filter::nearest);
    t.mask = gl::Texture2D(width, height, GL_R8, gl::Filter::nearest);
    t.output = gl::Texture2D(width, height, GL_RGBA8, gl::Filter::nearest);
    t.depth_fbo = gl::Framebuffer({}, &t.depth);
    t.lines_fbo = gl::Framebuffer({&t.lines}, nullptr);
    t.bloom_a_fbo = gl::Framebuffer({&t.bloom_a}, nullptr);
    t.bloom_b_fbo = gl::Framebuffer({&t.bloom_b}, nullptr);
    t.bloom_out_fbo = gl::Framebuffer({&t.bloom_out}, nullptr);
    t.mask_fbo = gl::Framebuffer({&t.mask}, nullptr);
    t.output_fbo = gl::Framebuffer({&t.output}, nullptr);
    t.canvas = gl::Texture2D(width, height, GL_RGBA8, gl::Filter::nearest);
    t.shrunk_depth = gl::Texture2D(width, height, depth_format, gl::Filter::nearest);
    t.halo = gl::Texture2D(width, height, GL_RG16F, gl::Filter::nearest);
    t.canvas_depth_fbo = gl::Framebuffer({&t.canvas}, &t.depth);
    t.canvas_fbo = gl::Framebuffer({&t.canvas}, nullptr);
    t.canvas_shrunk_fbo = gl::Framebuffer({&t.canvas}, &t.shrunk_depth);
    t.shrunk_fbo = gl::Framebuffer({}, &t.shrunk_depth);
    t.halo_fbo = gl::Framebuffer({&t.halo}, &t.shrunk_depth);
    if (s.beam.bloom == BloomKind::mip_chain) {
        int lw = bw, lh = bh;
        const std::size_t levels = std::clamp<std::size_t>(s.beam.mip_weights.size(), 1, 12);
        for (std::size_t k = 0; k < levels; ++k) {
            if (k > 0 && lw == 1 && lh == 1) break;
            t.bloom_mips.emplace_back(lw, lh, GL_RGBA16F, gl::Filter::linear);
            lw = std::max(1, lw / 2);
            lh = std::max(1, lh / 2);
        }
        for (const gl::Texture2D& level : t.bloom_mips)
            t.bloom_mip_fbos.emplace_back(std::vector{&level}, nullptr);
    }
    // The bloom's first level: bloom_a, or the chain's first.
    const gl::Texture2D& first_level = t.bloom_mips.empty() ? t.bloom_a : t.bloom_mips[0];
    t.first_down_fbo = gl::Framebuffer({&first_level}, nullptr);
    if (s.beam.phosphor != PhosphorDecay::off) {
        // Everything starts black, with no tile lit.
        t.phosphor = gl::Texture2D(width, height, GL_RGBA16F, gl::Filter::linear);
        glClearTexImage(t.phosphor.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
        t.picture_lit = gl::Texture2D(lit_x, lit_y, GL_R8UI, gl::Filter::nearest);
        glClearTexImage(t.picture_lit.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
        glClearTexImage(t.bloom_out.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        t.bloom_last = gl::Texture2D(bw, bh, GL_RGBA8, gl::Filter::linear);
        glClearTexImage(t.bloom_last.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        t.bloom_last_fbo = gl::Framebuffer({&t.bloom_last}, nullptr);
    }
    if (s.method == LineMethod::image_outline) {
        t.normals = gl::Texture2D(width, height, GL_RGBA8, gl::Filter::nearest);
        t.normals_fbo = gl::Framebuffer({&t.normals}, &t.depth);
    }
    return t;
}

}  // namespace bz::render
