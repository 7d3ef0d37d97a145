#pragma once
// Every knob of the line pipeline, and the named presets that set them all.
#include <string>
#include <string_view>
#include <vector>

namespace bz::render {

enum class DepthFormat {
    reversed_f32,      // 32-bit float depth, reversed-Z via glClipControl (default)
    conventional_d24,  // 24-bit fixed-point depth, [-1,1] clip (for comparison)
};

enum class BloomResolution { full = 1, half = 2, quarter = 4 };

// How feature lines are found.
enum class LineMethod {
    geometry,       // the geometry shader on triangle adjacency, with the spine test (default)
    image_outline,  // baseline: Sobel edges on the prepass depth and normals (pass_image_outline)
};

struct RenderSettings {
    std::string preset = "balanced";
    DepthFormat depth = DepthFormat::reversed_f32;
    int spine_samples = 1;          // 1 (the texel under the spine) or 4 (bilinear 2x2 around it)
    // The spine test compares the prepass with the exact plane of the edge's face; these say
    // how far the rasterised depth may sit from it (shaders/spine_test.glsl):
    float plane_tolerance_rel = 1e-5f;   // relative to the depth: float rounding
    float plane_tolerance_px = 0.0625f;  // pixels of the face's own depth slope: rasterisation
    // Relative bias where no plane is usable (a face seen edge-on), and the most the slope
    // allowance may add: a steep face must not see through a thin surface in front of it.
    float depth_bias = 5e-4f;
    float line_half_width_px = 2.0f;
    float crease_angle_deg = 60.0f;
    BloomResolution bloom_resolution = BloomResolution::half;
    int bloom_taps = 9;             // linear-sampled taps per direction (odd)
    float bloom_sigma_px = 4.0f;    // Gaussian sigma, in pixels of the bloom target
    float bloom_strength = 1.0f;
    float exposure = 1.0f;
    bool frustum_culling = true;
    bool lod = true;                // raise the crease threshold / use simplified meshes far away
    bool count_edges = false;       // count emitted feature edges (costs a query per frame)
    LineMethod method = LineMethod::geometry;
    bool instancing = true;         // false: one draw call per object (for measuring batching)
    // image_outline thresholds: relative depth step, and normal step as a crease angle.
    float outline_depth_threshold = 0.1f;
};

// "fast", "balanced" or "high"; throws UserError naming the valid ones otherwise.
RenderSettings preset(std::string_view name);
const std::vector<std::string>& preset_names();

}  // namespace bz::render
