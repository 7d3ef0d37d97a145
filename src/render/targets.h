#pragma once
// The offscreen images one frame renders into.
#include <array>
#include <glm/vec2.hpp>
#include <vector>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "render/frame_resources.h"
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
// The depth layers peeled for hidden lines by occlusion level (pass_occlusion_layers.cpp): the
// level is capped at geo::kMaxOcclusionLevel, so that many layers count every level exactly.
inline constexpr int kOcclusionLayers = 3;

// The images of one frame, each allocated only when the frame's pass list names it
// (frame_resources.h: `allocated`); what outlives the frame is in FrameHistory. No pass
// records here what another did: a pass asks the frame (FrameResources) or the history.
struct Targets {
    int width = 0;
    int height = 0;
    ResourceSet allocated;  // what make_targets was asked for
    gl::Texture2D depth;    // prepass depth (32F reversed-Z or 24-bit)
    // The compute prepass's nearest depth per pixel as float bits (R32UI, lines/prepass_raster.h),
    // merged into `depth` within the prepass; with reversed-Z depth where it may run.
    gl::Texture2D raster_depth;
    gl::Texture2D lines;    // HDR lines + HUD, RGBA16F, GL_MAX blended
    gl::Texture2D bloom_a;  // Gaussian bloom ping-pong at the bloom resolution
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
    // BloomChain::compute: the levels the compute walk takes (some of levels 1 .. n-1) as vec4
    // texels, one level after another (bloom_chain.comp), in place of their textures.
    gl::Buffer bloom_chain_texels;
    // Sparse composite (pass_tiles.cpp, shaders/beam/lit_tiles.glsl): the lit-tile marks (R8UI,
    // one texel per kLitTileSize square), cleared by the bloom, marked by its first downsample
    // (beam light) and its last step (glow); and the list of tiles to shade that tile_list.comp
    // builds from them, behind the indirect draw command it heads. Only where the bloom
    // resolution divides the size, so that the downsample's blocks cover every pixel exactly.
    gl::Texture2D lit_tiles;
    gl::Buffer tile_list;
    // How many tiles the list holds (one word, tile_list.comp adds each row's): read a frame
    // later by the bloom's choice of first downsample (RenderSettings::first_downsample).
    gl::Buffer lit_tile_count;
    // The screen tiles the beam lights (R8UI, like `tiles`): cleared by the line pass, marked by
    // the line and HUD fragments (shaders/beam/beam_tiles.glsl). The bloom's first downsample
    // reads only under them when a pass of its frame wrote them (FrameResources; a frame whose
    // lines come from elsewhere, the image-space outline, writes none: it then reads every
    // pixel).
    gl::Texture2D beam_tiles;
    // The bloom's first level.
    gl::Framebuffer first_down_fbo;
    // Hierarchical-Z culling (lines/hiz_culling.h): per fine and per coarse tile, the inverse
    // view depth of the farthest surface the prepass left (R32F).
    gl::Texture2D depth_tiles;
    gl::Texture2D depth_tiles_coarse;
    // Hidden lines by occlusion level (technical, vector-xray): the depth of the nearest, second
    // and third surfaces facing the eye at each pixel (pass_occlusion_layers.cpp), in the
    // prepass's depth format, and a depth-only framebuffer over each.
    std::array<gl::Texture2D, kOcclusionLayers> occlusion_layers;
    std::array<gl::Framebuffer, kOcclusionLayers> occlusion_layer_fbos;
};

// The bloom resolution's size of a `width` x `height` frame.
glm::ivec2 bloom_size(int width, int height, const RenderSettings& settings);

// The images `needed` names (Resource::target: the output image); the rest stay empty.
Targets make_targets(int width, int height, const RenderSettings& settings, ResourceSet needed);
// The same, keeping the images `old` (made at the same size and settings) already holds: a
// frame that needs more than the last keeps what the last one wrote.
Targets grow_targets(Targets&& old, int width, int height, const RenderSettings& settings,
                     ResourceSet needed);

// The bytes of GPU memory the targets hold (texels and buffers, as their formats store them
// uncompressed), for the measurement of what allocation from the pass list saves.
std::size_t allocated_bytes(const Targets& targets);
std::size_t texture_bytes(const gl::Texture2D& texture);

}  // namespace bz::render
