#pragma once
// Every knob of the line pipeline, and the named presets that set them all.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/style.h"

namespace bz::render {

enum class DepthFormat {
    reversed_f32,      // 32-bit float depth, reversed-Z via glClipControl (default)
    conventional_d24,  // 24-bit fixed-point depth, [-1,1] clip (for comparison)
};

enum class BloomResolution { full = 1, half = 2, quarter = 4 };

// Who rasterises the depth prepass's small triangles (render/lines/prepass_raster.h).
enum class PrepassRaster {
    automatic,  // compute on a software rasteriser where the frame has enough triangles
    pipeline,   // the GL pipeline draws every triangle
    compute,    // small clusters in a compute shader wherever the depth format allows it
};

// Who rules out, before edges.comp classifies them, the edges of the kept clusters that
// cannot be feature edges (render/lines/edge_prefilter.h). The same lines either way.
enum class EdgePrefilter {
    automatic,  // the CPU on a software rasteriser, where the shader's every branch runs
    gpu,        // none: edges.comp tests every edge of the kept clusters
    cpu,        // the CPU tests them first and lists only those that may be feature edges
};

// Who clears the frame's full-screen colour images (render/clear_image.h). The same pixels
// either way.
enum class ColourClears {
    automatic,  // the pipeline on a software rasteriser; on a GPU, whichever timed faster
    pipeline,   // glClear: the raster back end writes every pixel
    compute,    // a compute shader writes every texel, past the raster back end
};

// Who computes the bloom's mip chain past its first level (BloomKind::mip_chain;
// pass_bloom.cpp). The same sums up to the rounding of the levels' storage.
enum class BloomChain {
    automatic,  // compute on a software rasteriser, the pipeline on a GPU
    pipeline,   // one draw per level down and up: 13 at a quarter of 1280x720
    compute,    // one workgroup walks the levels of at most 128x128 texels in one dispatch
                // (bloom_chain.comp); larger ones are drawn
};

// How the mame beam's bloom reads the beam image into its first level (pass_bloom.cpp).
// The same picture either way.
enum class FirstDownsample {
    automatic,  // on a software rasteriser, dense when half or more of the screen's tiles were
                // lit the frame before (Targets::lit_tile_count), else sparse; sparse on a GPU
    sparse,     // the line stages mark the screen tiles their quads may light, and the
                // downsample reads the beam image under those tiles only
    dense,      // no marks; the downsample reads the whole beam image
};

// How feature lines are found.
enum class LineMethod {
    geometry_shader,  // a geometry shader per triangle on triangle adjacency (pass_lines.cpp)
    compute,          // a compute shader per unique edge fills the edge buffer, then one quad per
                      // edge (pass_edges.cpp, pass_edge_quads.cpp); same lines, same spine test
    image_outline,    // baseline: Sobel edges on the prepass depth and normals (pass_image_outline)
    automatic,        // "auto": per frame, geometry_shader or compute by what the frame submits
                      // (resolve_line_method); the renderer draws each frame with one of them
};

// "geometry_shader" (also "geometry", its old name), "compute", "auto" or "image_outline";
// throws UserError naming the valid ones otherwise.
LineMethod parse_line_method(std::string_view name);
const char* line_method_name(LineMethod method);
// The two methods that draw the same feature lines (not the image-space baseline, not auto,
// which draws each frame with one of these two).
const std::vector<LineMethod>& feature_line_methods();

// Without a measurement for the machine (RenderSettings::auto_compute_from_triangles,
// render/auto_threshold.h), LineMethod::automatic on a software rasteriser (llvmpipe) draws a
// frame with the compute method from this many submitted triangles (after culling and LOD,
// FrameStats::triangles_submitted) and with the geometry shader below. The compute path has
// fixed per-frame costs (dispatches, counters, the visibility pass, an indirect draw) but
// scales with llvmpipe's threads; the geometry shader runs on one thread at a cost per
// triangle. On a hardware GPU auto always draws with compute: on an NVIDIA H100 it was the
// faster method at every size measured, the 468-triangle classic level included. Measured:
// see docs/pipeline.md, "Line methods".
inline constexpr std::size_t kAutoComputeFromTriangles = 4000;
// The method that draws a frame of `triangles_submitted` triangles: `method` itself unless it
// is LineMethod::automatic. Depends on the frame's content and the renderer only, never on
// timings, so the same frame on the same machine always gets the same method.
// `measured`: the machine's measured crossing (render/auto_threshold.h), which replaces the
// built-in rule.
LineMethod resolve_line_method(LineMethod method, std::size_t triangles_submitted,
                               bool software_rasteriser,
                               std::optional<std::size_t> measured = std::nullopt);

// The method presets use: auto, which on llvmpipe is as fast as the geometry shader on small
// game frames and as the compute method on large scenes, and on a hardware GPU is the compute
// method; see docs/measurements/line-methods.md for the measurements behind it.
inline constexpr LineMethod kDefaultLineMethod = LineMethod::automatic;

// The vector beam: how a line's intensity becomes width and brightness, how lines combine,
// how the phosphor holds them, and the glow. The `classic` look is the original beamzone beam
// (constant width, GL_MAX, Gaussian bloom); `mame` follows MAME's vector renderer
// (src/emu/video/vector.cpp and its monochrome vector preset) and goes beyond it (dwell,
// overdrive defocus, frame-rate independent phosphor). Widths are full widths in pixels on a
// 1080-line screen, scaled to the target's height.
enum class BeamBlend { max, additive };

// MAME's unit of beam width, in pixels of a 1080-line screen. vector.cpp divides the width by
// VECTOR_WIDTH_DENOM (512) in coordinates normalised to the game screen, and render.cpp scales
// a line's width by the smaller of the screen container's x and y scales (its size in target
// pixels): one unit is 1/512 of the screen's smaller side, which for a landscape screen is its
// height. beamzone fills the window, so it scales by the target's height.
inline constexpr float kMameBeamWidthUnitPx = 1080.0f / 512.0f;
enum class PhosphorDecay { off, exponential, power_law };
enum class BloomKind { gaussian, mip_chain };

struct BeamSettings {
    std::string look = "classic";
    BeamBlend blend = BeamBlend::max;
    // Width = min + sigmoid(intensity * nominal, weight) * (max - min) (MAME's normalized
    // tunable sigmoid); min == max keeps the preset's constant line width.
    bool intensity_width = false;
    float width_min_px = 1.0f * kMameBeamWidthUnitPx;  // MAME's 1 and 4 (vector-mono.ini)
    float width_max_px = 4.0f * kMameBeamWidthUnitPx;
    float intensity_weight = 0.75f;
    float nominal = 0.75f;  // the MAME intensity (0..1) of a line of intensity 1
    float flicker = 0.0f;   // intensity -= intensity * random * flicker, per line
    // Dwell (beyond MAME, docs/sources.md): the beam spends a fixed time on every vector, so
    // short vectors and dots get more energy: gain = (length + dwell) / length, <= dwell_max.
    float dwell_px = 0.0f;  // at 1080 lines
    float dwell_max = 1.0f;
    // Overdrive (beyond MAME, docs/sources.md): above MAME intensity 1 the spot widens and
    // softens instead of clipping: width x (1 + defocus * excess), peak / that factor.
    float defocus = 0.0f;
    // MAME lengthens every vector by 3/8 of the beam's full width at each end
    // (src/emu/video/vector.cpp, "extend vector line by 3/8 beam_width on both sides"): this
    // share of the width is added past both end points. Visual only: whether an end shows is
    // still decided at the edge's own end point (shaders/beam/beam_ends.glsl).
    float end_lengthening = 0.0f;
    PhosphorDecay phosphor = PhosphorDecay::off;
    float persistence_ms = 20.0f;  // exponential: tau; power law: the time to half brightness
    float power_law_exponent = 2.0f;
    BloomKind bloom = BloomKind::gaussian;
    std::vector<float> mip_weights;  // mip_chain: weight of each level, half resolution first
    float bloom_threshold = 0.0f;    // glow only from brightness above this (peak channel) ...
    float bloom_knee = 0.0f;         // ... with a soft knee of this half-width
    // Black level of the glow: this much is taken off the finished bloom, so the wide levels'
    // faint wash over the whole screen stays black (a tube's brightness knob turned down).
    float bloom_floor = 0.0f;
    bool overlay = false;      // Battlezone's overlay: top 20% red, the rest green
    bool colour_safe = false;  // the overlay's red as violet-blue (red-green colour blindness)
    float refresh_hz = 0.0f;   // > 0: hold frames to this refresh (the original's ~41 Hz)
};

struct RenderSettings {
    std::string preset = "balanced";
    DepthFormat depth = DepthFormat::reversed_f32;
    // The spine test reads the one prepass texel under the spine point (a 2x2 bilinear filter
    // scored no better on real models) and compares it with the exact plane of the edge's face;
    // these say how far the rasterised depth may sit from it (shaders/lines/spine_test.glsl):
    float plane_tolerance_rel = 1e-5f;   // relative to the depth: float rounding
    float plane_tolerance_px = 0.0625f;  // pixels of the face's own depth slope: rasterisation
    // Relative bias where no plane is usable (a face seen edge-on), and the most the slope
    // allowance may add: a steep face must not see through a thin surface in front of it.
    float depth_bias = 2e-4f;
    float line_half_width_px = 2.0f;
    // LineMethod::compute: the spine test runs once per sample this many pixels apart along
    // each edge (pass_spine_visibility.cpp) and fragments look it up; 0 runs it in every line
    // fragment instead. 1 px scored the same F1 as every fragment (bench --accuracy).
    float spine_sample_spacing_px = 1.0f;
    float crease_angle_deg = 60.0f;
    // Draw the edges between faces of different materials (geo::AdjacencyMesh::material_edges)
    // as lines, like creases. Off by default: a model's materials often split flat surfaces
    // for textures the vector look never shows; a level turns it on ([render] material_lines).
    bool material_lines = false;
    // Draw where the surfaces of two occluding objects cross (or two faces of one that share
    // no vertex) as lines, like creases (render/gpu_scene/intersection_cache.h). Off by
    // default, like material lines: a model built from parts pushed into each other would get
    // lines its author never saw; a level turns it on ([render] intersection_lines).
    bool intersection_lines = false;
    BloomResolution bloom_resolution = BloomResolution::half;
    int bloom_taps = 9;           // linear-sampled taps per direction (odd)
    float bloom_sigma_px = 4.0f;  // Gaussian sigma, in pixels of the bloom target
    float bloom_strength = 1.0f;
    float exposure = 1.0f;
    bool frustum_culling = true;
    // Draw only the triangle clusters in view in the depth prepass and the fills, and of a
    // closed mesh seen from outside only those not wholly facing away (triangle_culling.h);
    // false: whole meshes (the same picture, for comparing).
    bool cluster_culling = true;
    // LineMethod::compute with occlusion: skip the edge clusters the prepass hides wholly
    // (lines/hiz_culling.h) when the frame has enough edges for it to pay. The same picture
    // either way. Off by default: measured, it cost more than it saved on the H100 and gained
    // nothing clear on llvmpipe in the scenes here (docs/measurements/hiz-culling.md).
    bool hiz_culling = false;
    // The prepass's small clusters rasterised by a compute shader on every thread, where the
    // GL pipeline would set up each triangle on one (llvmpipe). The same depth at every pixel
    // centre up to float rounding; automatic chooses it on software rasterisers only.
    PrepassRaster prepass_raster = PrepassRaster::automatic;
    EdgePrefilter edge_prefilter = EdgePrefilter::automatic;
    ColourClears colour_clears = ColourClears::automatic;
    BloomChain bloom_chain = BloomChain::automatic;
    FirstDownsample first_downsample = FirstDownsample::automatic;
    bool lod = true;           // raise the crease threshold / use simplified meshes far away
    bool count_edges = false;  // count emitted feature edges (costs a query per frame)
    LineMethod method = kDefaultLineMethod;
    // LineMethod::automatic: compute from this many submitted triangles, as measured on this
    // machine (render/auto_threshold.h, app/line_method_profile.h); unset: the built-in rule.
    std::optional<std::size_t> auto_compute_from_triangles;
    bool instancing = true;  // false: one draw call per object (for measuring batching)
    // image_outline thresholds: relative depth step, and normal step as a crease angle.
    float outline_depth_threshold = 0.1f;
    // Draw every frame in this style instead of the frame list's own (bench --style, the
    // sweep's per-style rows); none: the frame's.
    std::optional<scene::Style> style;
    // The halo style's cubic silhouette smoothing (Loviscach); off to compare with the plain
    // polygonal outline (render --no-smoothing, the smoothing test).
    bool cubic_smoothing = true;
    // Toon and pop-art outlines as one-sided quads (extruded outward from silhouettes and
    // depth-tested) instead of the centred, spine-tested ones (Castro & Macedo's two variants).
    bool one_sided_outlines = false;
    BeamSettings beam;
    // false: every frame starts without a past (phosphor and glow from black, no held frame),
    // so nothing trails whatever the beam look: the --edit viewer.
    bool keep_history = true;
    // Composite only the screen tiles that bloom found lit (pass_tiles.cpp), and in the filled
    // styles lay the HUD only over the tiles it lit (pass_ink_composite.cpp); false: every
    // pixel (the same picture, for comparing).
    bool sparse_composite = true;
    // true: the dark looks' HUD is drawn before the bloom and glows like the scene (and keeps
    // the scene's beam width); false: after it, without glow, so that text keeps its contrast
    // and menus leave no haze (render/beam/pass_hud.cpp). Tests that draw analytic screen
    // lines as HUD lines to exercise the bloom set it.
    bool hud_glow = false;
    // true: in a style that draws hidden lines by occlusion level (technical), render_mask
    // marks each pixel a line's spine crosses with 255 - 64 x its level (255 visible, 191, 128,
    // 64 for levels 1 to 3), the lowest level winning, instead of the visible lines alone: the
    // GPU's levels, for comparing with the exact reference's.
    bool mask_occlusion_levels = false;
};

// "fast", "balanced" or "high"; throws UserError naming the valid ones otherwise.
RenderSettings preset(std::string_view name);
const std::vector<std::string>& preset_names();

// "classic" or "mame"; throws UserError naming the valid ones otherwise.
BeamSettings beam_look(std::string_view name);
// The beam look `play`, `render` and `bench` use when nothing names one. `mame`: it is what
// the game ships and the player sees, so a still frame from `render` and a `bench` run show
// and time the player's picture (a first frame has no phosphor past, so `render` stays one
// deterministic picture); `--beam classic` keeps the cheaper, plainer look.
inline constexpr std::string_view kDefaultBeamLook = "mame";
const std::vector<std::string>& beam_look_names();

}  // namespace bz::render
