#pragma once
// The offscreen images one frame renders into.
#include <array>
#include <vector>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "render/settings.h"

namespace bz::render {

// The beam's screen tiles, in pixels (shaders/beam/screen_tiles.glsl gets it too): where the
// line and HUD quads may light, for the bloom's sparse first downsample.
inline constexpr int kScreenTileSize = 32;
// The sparse composite's lit tiles, in pixels (shaders/beam/lit_tiles.glsl gets it too). A
// multiple of every bloom divisor (a downsample block lies in one tile). Smaller tiles follow
// a thin line's glow more closely; the list keeps the vertex work to the lit ones.
inline constexpr int kLitTileSize = 16;
static_assert(kLitTileSize % static_cast<int>(BloomResolution::quarter) == 0);

struct Targets {
    int width = 0;
    int height = 0;
    gl::Texture2D depth;    // prepass depth (32F reversed-Z or 24-bit)
    gl::Texture2D lines;    // HDR lines + HUD, RGBA16F, GL_MAX blended
    gl::Texture2D bloom_a;  // bloom ping-pong at the bloom resolution
    gl::Texture2D bloom_b;
    gl::Texture2D
        bloom_out;  // the finished bloom, RGBA8 sqrt-encoded (shaders/beam/bloom_encoding.glsl)
    gl::Texture2D mask;     // R8 visible-spine mask
    gl::Texture2D output;   // RGBA8 composite, for PNGs and screenshots
    gl::Texture2D normals;  // RGBA8 face normals, only for LineMethod::image_outline
    // Filled styles (render/styles/): the paper with fills and ink strokes, display-referred
    // RGBA8; the halo's shrunk-mesh depth mask; its off-screen soft-halo buffer (MAX blended:
    // r = halo strength, g = inverse view depth of the stroke that cast it).
    gl::Texture2D canvas;
    gl::Texture2D shrunk_depth;
    gl::Texture2D halo;
    gl::Framebuffer canvas_depth_fbo;   // canvas + the prepass depth (fills write both)
    gl::Framebuffer canvas_fbo;         // canvas alone (strokes read the depth as a texture)
    gl::Framebuffer canvas_shrunk_fbo;  // canvas + shrunk depth (halo strokes depth-test it)
    gl::Framebuffer shrunk_fbo, halo_fbo;
    gl::Framebuffer depth_fbo, lines_fbo, bloom_a_fbo, bloom_b_fbo, bloom_out_fbo, mask_fbo,
        output_fbo;
    gl::Framebuffer normals_fbo;  // normals + depth
    // BloomKind::mip_chain: level 0 at the bloom resolution, each next one half as large.
    std::vector<gl::Texture2D> bloom_mips;
    std::vector<gl::Framebuffer> bloom_mip_fbos;
    // Phosphor persistence: the picture (RGBA16F, alpha = age for the power law), updated in
    // place by the composite, which loads each pixel's own texel and stores the new value only
    // where it changed. Only when BeamSettings::phosphor is on.
    gl::Texture2D phosphor;
    // Which lit tiles of the picture hold light (R8UI, like lit_tiles): read by tile_list.comp
    // (those must be decayed this frame), then cleared and marked again by the composite.
    gl::Texture2D picture_lit;
    // Last frame's finished bloom (like bloom_out, which it swaps with each frame): the glow
    // persists with the phosphor (shaders/beam/glow_persistence.glsl).
    gl::Texture2D bloom_last;
    gl::Framebuffer bloom_last_fbo;
    bool glow_history_valid = true;  // false after a phosphor frame drawn without bloom
    // Sparse composite (pass_tiles.cpp, shaders/beam/lit_tiles.glsl): the lit-tile marks (R8UI,
    // one texel per kLitTileSize square), cleared by the bloom, marked by its first downsample
    // (beam light) and its last step (glow); and the list of tiles to shade that tile_list.comp
    // builds from them, behind the indirect draw command it heads. Only where the bloom
    // resolution divides the size, so that the downsample's blocks cover every pixel exactly.
    gl::Texture2D lit_tiles;
    gl::Buffer tile_list;
    // The screen tiles the beam lights (R8UI, like `tiles`): cleared by the line pass, marked by
    // the line and HUD fragments (shaders/beam/beam_tiles.glsl), and valid until the bloom's
    // first downsample has read them (a frame whose lines come from elsewhere, the image-space
    // outline, leaves them invalid: the downsample then reads every pixel).
    gl::Texture2D beam_tiles;
    bool beam_tiles_valid = false;
    bool tiles_valid = false;  // the list describes the current bloom (pass_tiles ran on it)
    // The bloom's first level.
    gl::Framebuffer first_down_fbo;
};

Targets make_targets(int width, int height, const RenderSettings& settings);

}  // namespace bz::render
