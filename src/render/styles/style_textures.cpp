#include "render/styles/style_textures.h"

#include <algorithm>
#include <cmath>

#include "core/rng.h"

namespace bz::render {

namespace {

constexpr int kNoiseSize = 256;
constexpr int kProfileWidth = 64;
constexpr int kProfileRows = 4;
constexpr int kOffsetSize = 64;

void wrap_repeat(const gl::Texture2D& t) {
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

}  // namespace

std::vector<unsigned char> stroke_noise_texels(int size) {
    Rng rng(0x5eed5ce7c4ull);  // fixed: the drawing is part of the style, not of the run
    std::vector<unsigned char> v(static_cast<std::size_t>(size) * size * 4);
    for (auto& b : v) b = static_cast<unsigned char>(rng.below(256));
    return v;
}

std::vector<float> halo_profile_texels(int width, int rows) {
    std::vector<float> v(static_cast<std::size_t>(width) * rows * 2);
    for (int row = 0; row < rows; ++row) {
        // Each stroke a little different: a narrower core and a softer edge further down.
        const double core = 0.55 - 0.08 * row;
        for (int i = 0; i < width; ++i) {
            const double x = (i + 0.5) / width;  // 0 inner edge .. 1 outer edge
            const double d = std::abs(x - 0.5) * 2.0;
            const double ink = d < core ? 1.0 : std::max(0.0, 1.0 - (d - core) / (1.0 - core));
            // The halo: full next to the stroke, fading smoothly to nothing at its reach.
            const double fade = std::clamp((x - 0.5) / 0.5, 0.0, 1.0);
            const double halo = 1.0 - fade * fade * (3.0 - 2.0 * fade);
            const std::size_t k = (static_cast<std::size_t>(row) * width + i) * 2;
            v[k] = static_cast<float>(ink * ink * (3.0 - 2.0 * ink));
            v[k + 1] = static_cast<float>(halo);
        }
    }
    return v;
}

StyleTextures make_style_textures() {
    StyleTextures t;
    t.noise = gl::Texture2D(kNoiseSize, kNoiseSize, GL_RGBA8, gl::Filter::nearest);
    const std::vector<unsigned char> noise = stroke_noise_texels(kNoiseSize);
    glTextureSubImage2D(t.noise.id(), 0, 0, 0, kNoiseSize, kNoiseSize, GL_RGBA, GL_UNSIGNED_BYTE,
                        noise.data());
    wrap_repeat(t.noise);

    t.profile = gl::Texture2D(kProfileWidth, kProfileRows, GL_RG16F, gl::Filter::linear);
    const std::vector<float> profile = halo_profile_texels(kProfileWidth, kProfileRows);
    glTextureSubImage2D(t.profile.id(), 0, 0, 0, kProfileWidth, kProfileRows, GL_RG, GL_FLOAT,
                        profile.data());

    // Smooth offsets: a few low-frequency sines with random phases, in [-1, 1] pixels.
    Rng rng(0x0ff5e7ull);
    const double ph[4] = {rng.uniform(0.0, 6.283), rng.uniform(0.0, 6.283), rng.uniform(0.0, 6.283),
                          rng.uniform(0.0, 6.283)};
    std::vector<float> offset(static_cast<std::size_t>(kOffsetSize) * kOffsetSize * 2);
    for (int y = 0; y < kOffsetSize; ++y) {
        for (int x = 0; x < kOffsetSize; ++x) {
            const double u = 6.283185307 * x / kOffsetSize, w = 6.283185307 * y / kOffsetSize;
            const std::size_t k = (static_cast<std::size_t>(y) * kOffsetSize + x) * 2;
            offset[k] =
                static_cast<float>(0.6 * std::sin(u + ph[0]) + 0.4 * std::sin(2.0 * w + ph[1]));
            offset[k + 1] =
                static_cast<float>(0.6 * std::sin(w + ph[2]) + 0.4 * std::sin(2.0 * u + ph[3]));
        }
    }
    t.offset = gl::Texture2D(kOffsetSize, kOffsetSize, GL_RG16F, gl::Filter::linear);
    glTextureSubImage2D(t.offset.id(), 0, 0, 0, kOffsetSize, kOffsetSize, GL_RG, GL_FLOAT,
                        offset.data());
    wrap_repeat(t.offset);
    return t;
}

}  // namespace bz::render
