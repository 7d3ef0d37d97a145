#pragma once
// Every knob of the line pipeline, and the named presets that set them all.
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

// How feature lines are found.
enum class LineMethod {
    geometry,       // the geometry shader on triangle adjacency, with the spine test (default)
    image_outline,  // baseline: Sobel edges on the prepass depth and normals (pass_image_outline)
};

struct RenderSettings {
    std::string preset = "balanced";
    DepthFormat depth = DepthFormat::reversed_f32;
    int spine_samples = 1;          // 1 (centre pixel) or 9 (3x3 neighbourhood)
    float depth_bias = 2e-3f;       // relative view-space bias of the spine test
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
    // Draw every frame in this style instead of the frame list's own (bench --style, the
    // sweep's per-style rows); none: the frame's.
    std::optional<scene::Style> style;
    // The halo style's cubic silhouette smoothing (seed 004); off to compare with the plain
    // polygonal outline (render --no-smoothing, the smoothing test).
    bool cubic_smoothing = true;
};

// "fast", "balanced" or "high"; throws UserError naming the valid ones otherwise.
RenderSettings preset(std::string_view name);
const std::vector<std::string>& preset_names();

}  // namespace bz::render
