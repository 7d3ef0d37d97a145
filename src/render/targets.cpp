#include "render/targets.h"

#include <algorithm>

#include "render/lines/hiz_culling.h"
#include "render/shader_interface.h"

namespace bz::render {

glm::ivec2 bloom_size(int width, int height, const RenderSettings& s) {
    const int f = static_cast<int>(s.bloom_resolution);
    return {std::max(1, width / f), std::max(1, height / f)};
}

namespace {

const GLenum kNoFormat = 0;

GLenum depth_format(const RenderSettings& s) {
    return s.depth == DepthFormat::reversed_f32 ? GL_DEPTH_COMPONENT32F : GL_DEPTH_COMPONENT24;
}

// The bloom's working levels: the Gaussian's ping-pong pair, or MAME's chain.
void make_bloom_chain(Targets& t, glm::ivec2 b, const RenderSettings& s) {
    if (s.beam.bloom == BloomKind::mip_chain) {
        int lw = b.x, lh = b.y;
        std::size_t texels = 0;  // levels 1 .. n-1 (Targets::bloom_chain_texels)
        const std::size_t levels =
            std::clamp<std::size_t>(s.beam.mip_weights.size(), 1, kMaxBloomLevels);
        for (std::size_t k = 0; k < levels; ++k) {
            if (k > 0 && lw == 1 && lh == 1) break;
            t.bloom_mips.emplace_back(lw, lh, GL_RGBA16F, gl::Filter::linear);
            if (k > 0) texels += static_cast<std::size_t>(lw) * static_cast<std::size_t>(lh);
            lw = std::max(1, lw / 2);
            lh = std::max(1, lh / 2);
        }
        t.bloom_chain_texels.set_data(nullptr, std::max<std::size_t>(texels, 1) * 4 * sizeof(float),
                                      GL_DYNAMIC_COPY);
    } else {
        t.bloom_a = gl::Texture2D(b.x, b.y, GL_RGBA16F, gl::Filter::linear);
        t.bloom_b = gl::Texture2D(b.x, b.y, GL_RGBA16F, gl::Filter::linear);
    }
}

// The images of `needed`, taken from `old` where it holds them (same size and settings), so
// that growing the set keeps what the frame before wrote (a held frame shows it again).
void make_images(Targets& t, Targets& old, const RenderSettings& s, ResourceSet needed) {
    const int width = t.width, height = t.height;
    const auto wants = [&](Resource r) { return needed.has(r); };
    const auto kept = [&](Resource r) { return old.allocated.has(r); };
    if (wants(Resource::depth) || wants(Resource::normals) || wants(Resource::canvas)) {
        t.depth = kept(Resource::depth)
                      ? std::move(old.depth)
                      : gl::Texture2D(width, height, depth_format(s), gl::Filter::nearest);
        t.allocated.add(Resource::depth);
        if (s.depth == DepthFormat::reversed_f32 && s.prepass_raster != PrepassRaster::pipeline) {
            t.raster_depth = old.raster_depth && kept(Resource::depth)
                                 ? std::move(old.raster_depth)
                                 : gl::Texture2D(width, height, GL_R32UI, gl::Filter::nearest);
        }
    }
    if (wants(Resource::lines)) {
        t.lines = kept(Resource::lines)
                      ? std::move(old.lines)
                      : gl::Texture2D(width, height, GL_RGBA16F, gl::Filter::linear);
    }
    const glm::ivec2 b = bloom_size(width, height, s);
    if (wants(Resource::bloom_chain)) {
        if (kept(Resource::bloom_chain)) {
            t.bloom_a = std::move(old.bloom_a);
            t.bloom_b = std::move(old.bloom_b);
            t.bloom_mips = std::move(old.bloom_mips);
            t.bloom_chain_texels = std::move(old.bloom_chain_texels);
        } else {
            make_bloom_chain(t, b, s);
        }
    }
    if (wants(Resource::bloom_out)) {
        if (kept(Resource::bloom_out)) {
            t.bloom_out = std::move(old.bloom_out);
        } else {
            t.bloom_out = gl::Texture2D(b.x, b.y, GL_RGBA8, gl::Filter::linear);
            // With the phosphor it swaps with the glow history each frame: it starts black too.
            if (s.beam.phosphor != PhosphorDecay::off)
                glClearTexImage(t.bloom_out.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        }
    }
    // Only where the bloom resolution divides the size (Targets::lit_tiles).
    const int f = static_cast<int>(s.bloom_resolution);
    if ((wants(Resource::lit_tiles) || wants(Resource::tile_list)) && width % f == 0 &&
        height % f == 0) {
        if (old.lit_tiles) {
            t.lit_tiles = std::move(old.lit_tiles);
            t.tile_list = std::move(old.tile_list);
            t.lit_tile_count = std::move(old.lit_tile_count);
        } else {
            const int lit_x = (width + kLitTileSize - 1) / kLitTileSize;
            const int lit_y = (height + kLitTileSize - 1) / kLitTileSize;
            t.lit_tiles = gl::Texture2D(lit_x, lit_y, GL_R8UI, gl::Filter::nearest);
            // The draw command (4 words), then one word per tile at most.
            const std::size_t words = 4 + static_cast<std::size_t>(lit_x) * lit_y;
            t.tile_list.set_data(nullptr, words * sizeof(GLuint), GL_DYNAMIC_DRAW);
            const GLuint none = 0;
            t.lit_tile_count.set_data(&none, sizeof(none), GL_DYNAMIC_READ);
        }
    }
    if (wants(Resource::beam_tiles)) {
        const int tiles_x = (width + kScreenTileSize - 1) / kScreenTileSize;
        const int tiles_y = (height + kScreenTileSize - 1) / kScreenTileSize;
        t.beam_tiles = kept(Resource::beam_tiles)
                           ? std::move(old.beam_tiles)
                           : gl::Texture2D(tiles_x, tiles_y, GL_R8UI, gl::Filter::nearest);
    }
    const auto image = [&](Resource r, gl::Texture2D Targets::*member, GLenum format,
                           gl::Filter filter) {
        if (!wants(r) || format == kNoFormat) return;
        t.*member = kept(r) ? std::move(old.*member) : gl::Texture2D(width, height, format, filter);
    };
    if (wants(Resource::depth_tiles)) {
        if (kept(Resource::depth_tiles)) {
            t.depth_tiles = std::move(old.depth_tiles);
            t.depth_tiles_coarse = std::move(old.depth_tiles_coarse);
        } else {
            const DepthTileGrid grid = depth_tile_grid(width, height);
            t.depth_tiles = gl::Texture2D(grid.fine.x, grid.fine.y, GL_R32F, gl::Filter::nearest);
            t.depth_tiles_coarse =
                gl::Texture2D(grid.coarse.x, grid.coarse.y, GL_R32F, gl::Filter::nearest);
        }
    }
    if (wants(Resource::peel_layers)) {
        for (int i = 0; i < kOcclusionLayers; ++i)
            t.occlusion_layers[i] =
                kept(Resource::peel_layers)
                    ? std::move(old.occlusion_layers[i])
                    : gl::Texture2D(width, height, depth_format(s), gl::Filter::nearest);
    }
    image(Resource::mask, &Targets::mask, GL_R8, gl::Filter::nearest);
    image(Resource::target, &Targets::output, GL_RGBA8, gl::Filter::nearest);
    image(Resource::canvas, &Targets::canvas, GL_RGBA8, gl::Filter::nearest);
    image(Resource::normals, &Targets::normals, GL_RGBA8, gl::Filter::nearest);
    image(Resource::halo, &Targets::halo, GL_RG16F, gl::Filter::nearest);
    if (wants(Resource::halo)) t.allocated.add(Resource::shrunk_depth);  // its depth test
    if (t.allocated.has(Resource::shrunk_depth)) {
        t.shrunk_depth = kept(Resource::shrunk_depth)
                             ? std::move(old.shrunk_depth)
                             : gl::Texture2D(width, height, depth_format(s), gl::Filter::nearest);
    }
}

// The framebuffers over whichever images there are.
void make_framebuffers(Targets& t) {
    const auto fbo = [](gl::Framebuffer& out, const gl::Texture2D* colour,
                        const gl::Texture2D* depth) {
        if ((colour && !*colour) || (depth && !*depth)) return;
        std::vector<const gl::Texture2D*> colours;
        if (colour) colours.push_back(colour);
        out = gl::Framebuffer(colours, depth);
    };
    fbo(t.depth_fbo, nullptr, &t.depth);
    fbo(t.lines_fbo, &t.lines, nullptr);
    fbo(t.bloom_a_fbo, &t.bloom_a, nullptr);
    fbo(t.bloom_b_fbo, &t.bloom_b, nullptr);
    fbo(t.bloom_out_fbo, &t.bloom_out, nullptr);
    fbo(t.mask_fbo, &t.mask, nullptr);
    fbo(t.output_fbo, &t.output, nullptr);
    fbo(t.canvas_depth_fbo, &t.canvas, &t.depth);
    fbo(t.canvas_fbo, &t.canvas, nullptr);
    fbo(t.canvas_shrunk_fbo, &t.canvas, &t.shrunk_depth);
    fbo(t.shrunk_fbo, nullptr, &t.shrunk_depth);
    fbo(t.halo_fbo, &t.halo, &t.shrunk_depth);
    fbo(t.normals_fbo, &t.normals, &t.depth);
    for (int i = 0; i < kOcclusionLayers; ++i)
        fbo(t.occlusion_layer_fbos[i], nullptr, &t.occlusion_layers[i]);
    for (const gl::Texture2D& level : t.bloom_mips)
        t.bloom_mip_fbos.emplace_back(std::vector{&level}, nullptr);
    // The bloom's first level: bloom_a, or the chain's first.
    if (!t.bloom_mips.empty()) {
        t.first_down_fbo = gl::Framebuffer({&t.bloom_mips[0]}, nullptr);
    } else if (t.bloom_a) {
        t.first_down_fbo = gl::Framebuffer({&t.bloom_a}, nullptr);
    }
}

}  // namespace

Targets make_targets(int width, int height, const RenderSettings& s, ResourceSet needed) {
    Targets none;
    return grow_targets(std::move(none), width, height, s, needed);
}

Targets grow_targets(Targets&& old, int width, int height, const RenderSettings& s,
                     ResourceSet needed) {
    Targets t;
    t.width = width;
    t.height = height;
    t.allocated = needed;
    make_images(t, old, s, needed);
    make_framebuffers(t);
    return t;
}

std::size_t texture_bytes(const gl::Texture2D& texture) {
    if (!texture) return 0;
    std::size_t texel = 4;  // RGBA8, RG16F, 24- and 32-bit depth
    switch (texture.format()) {
        case GL_RGBA16F:
            texel = 8;
            break;
        case GL_R8:
        case GL_R8UI:
            texel = 1;
            break;
        default:
            break;
    }
    return texel * static_cast<std::size_t>(texture.width()) *
           static_cast<std::size_t>(texture.height());
}

std::size_t allocated_bytes(const Targets& t) {
    std::size_t bytes = 0;
    for (const gl::Texture2D* tex :
         {&t.depth, &t.lines, &t.bloom_a, &t.bloom_b, &t.bloom_out, &t.mask, &t.output, &t.normals,
          &t.canvas, &t.shrunk_depth, &t.halo, &t.lit_tiles, &t.beam_tiles, &t.depth_tiles,
          &t.depth_tiles_coarse, &t.raster_depth})
        bytes += texture_bytes(*tex);
    for (const gl::Texture2D& level : t.bloom_mips) bytes += texture_bytes(level);
    for (const gl::Texture2D& layer : t.occlusion_layers) bytes += texture_bytes(layer);
    if (t.lit_tiles) bytes += t.tile_list.size();
    if (!t.bloom_mips.empty()) bytes += t.bloom_chain_texels.size();
    return bytes;
}

}  // namespace bz::render
