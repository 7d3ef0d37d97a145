#pragma once
// The vector-line renderer: one frame is the style's list of passes (frame_passes.cpp), e.g.
//   prepass -> [edges -> visibility ->] lines -> hud -> bloom -> [tiles ->] composite,
// each in its own file under src/render/ and timed under its own name.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/pass_timer.h"
#include "gl/texture.h"
#include "render/clear_image.h"
#include "render/frame_history.h"
#include "render/frame_resources.h"
#include "render/gpu_scene/intersection_cache.h"
#include "render/gpu_scene/triangle_culling.h"
#include "render/lines/edge_buffer.h"
#include "render/lines/edge_culling.h"
#include "render/settings.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::render {

// How a frame's mip-chain bloom went past its first level (BloomChain; pass_bloom.cpp): the
// levels past level 0 drawn one by one by the pipeline, then those walked by one compute
// dispatch. Both zero: no mip-chain bloom this frame.
struct BloomChainSplit {
    std::size_t drawn = 0;
    std::size_t walked = 0;
};

enum class FirstDownsampleRead {
    none,          // no bloom this frame
    marked_tiles,  // the tiles the line and HUD stages marked
    whole_image,
};

struct FrameStats {
    std::size_t objects_drawn = 0;
    std::size_t objects_culled = 0;
    std::size_t triangles_submitted = 0;
    // Counted only when RenderSettings::count_edges is on, and read back as late as the pass
    // times (EdgeCounter): after render(), the count of the frame pass_times_latency() frames
    // ago (the frame itself with cpu_finish timing or none).
    std::size_t feature_edges = 0;
    // The method that drew the frame's lines: LineMethod::automatic's choice for it.
    LineMethod line_method = kDefaultLineMethod;
    // LineMethod::compute: what culling before per-edge work left to the edge pass
    // (render/lines/edge_culling.h); zero with the geometry shader.
    EdgeCullStats edge_culling;
    // What cluster culling left to the depth prepass (render/gpu_scene/triangle_culling.h).
    TriangleCullStats triangle_culling;
    // Intersection lines (RenderSettings::intersection_lines): what the cache did this frame,
    // and how many segments went to the GPU (those whose objects are drawn at full detail).
    IntersectionStats intersections;
    std::size_t intersection_records = 0;
    BloomChainSplit bloom_chain;
    // What the bloom's first downsample read of the beam image (RenderSettings::first_downsample).
    FirstDownsampleRead first_downsample = FirstDownsampleRead::none;
};

class Renderer {
  public:
    // Pass as target_fbo to composite into the renderer's own RGBA8 image (headless use).
    static constexpr unsigned kOffscreen = ~0u;

    // Needs a current GL 4.5 context. Throws UserError if a shader does not compile.
    Renderer(const RenderSettings& settings, int width, int height, gl::TimingMethod timing);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void resize(int width, int height);
    void set_settings(const RenderSettings& settings);
    const RenderSettings& settings() const;
    // The line method the last render() or render_mask() drew with: settings().method, or
    // with LineMethod::automatic the one it chose for that frame (resolve_line_method).
    LineMethod line_method_drawn() const;

    // Draws the frame into the renderer's own targets and composites it to `target_fbo`
    // (0 = the window, kOffscreen = own image for read_color). Meshes are uploaded on first
    // use and when their version changes.
    void render(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                unsigned target_fbo = 0);

    // The 1-pixel visible-spine mask of the last frame's geometry (255 = lit), row 0 at top.
    std::vector<std::uint8_t> render_mask(const scene::FrameList& frame,
                                          const scene::MeshLibrary& meshes);
    // The final composited colour of the last render(), RGBA8, row 0 at the top (works for
    // kOffscreen and, before the swap, for the window).
    std::vector<std::uint8_t> read_color();
    // The HDR lines target (lines + HUD, before bloom) of the last render(): RGBA float,
    // row 0 at the top. For checks such as "no NaN or Inf pixels".
    std::vector<float> read_lines_hdr();
    // The depth the last render()'s prepass (or fill) left, one float per pixel in the depth
    // convention's own values, in GL's order (row 0 at the bottom).
    std::vector<float> read_depth();
    // The picture of the last render() as bloom and composite saw it: the lines target, or,
    // with phosphor persistence on, this frame's lines over the decayed earlier pictures.
    std::vector<float> read_picture_hdr();
    // The screen tiles (kLitTileSize squares, in GL's order: tile (0, 0) holds pixel row 0 at
    // the bottom) the last render()'s sparse composite shaded, sorted by row, then column;
    // empty when it composited every pixel (RenderSettings::sparse_composite off, no bloom, or
    // a size the bloom does not divide).
    std::vector<glm::ivec2> read_lit_tiles();
    // The edge buffer's records as its last fill (an edges pass, with any intersection lines)
    // left them, those that fit its capacity; empty before any fill. For tests.
    std::vector<EdgeRecord> read_edge_records();
    // The last render()'s finished bloom, RGBA8 sqrt-encoded (shaders/beam/bloom_encoding.glsl)
    // at the bloom resolution, in GL's order (row 0 at the bottom), with its size.
    std::vector<std::uint8_t> read_bloom(glm::ivec2* size);

    // Recompiles every shader from shaders/. On error keeps the old programs and returns false
    // with the message (file:line:col) in *error.
    bool reload_shaders(std::string* error);

    const std::vector<gl::PassTime>& pass_times() const;
    // How many frames old pass_times() is after a render() (0 for cpu_finish; the timer
    // query read-back delay for gpu_queries).
    int pass_times_latency() const;
    gl::TimingMethod timing_method() const;
    // GPU meshes uploaded so far: one per model used, plus simplified ones for distance LOD.
    std::size_t gpu_mesh_uploads() const;
    const FrameStats& stats() const;
    // Whether colour clears run by compute (clear_image.h); under ColourClears::automatic on a
    // GPU this times both paths at the frame's size first, once per size.
    bool colour_clears_by_compute();
    // That timing, where one was taken.
    std::optional<ClearTiming> colour_clear_timing() const;
    // The edge clusters hierarchical-Z culling skipped in the last frame's edges pass
    // (lines/hiz_culling.h). Reads the GPU's count now: a stall, for reports and tests.
    std::size_t hiz_hidden_clusters() const;
    // The images the frames drawn so far had allocated (from their pass lists, frame_passes.h;
    // a style change or a cut of the targets starts again), and the bytes they and the view's
    // history hold.
    ResourceSet allocated_resources() const;
    std::size_t allocated_bytes() const;
    // What the view's history holds now, and why it last forgot (frame_history.h).
    ResourceSet history_held() const;
    HistoryCut history_last_cut() const;
    int width() const;
    int height() const;

  private:
    std::vector<float> read_hdr(const gl::Texture2D& texture);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace bz::render
