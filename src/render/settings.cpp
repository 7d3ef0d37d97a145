#include "render/settings.h"

#include "core/error.h"

namespace bz::render {

const std::vector<std::string>& preset_names() {
    static const std::vector<std::string> names = {"fast", "balanced", "high"};
    return names;
}

RenderSettings preset(std::string_view name) {
    RenderSettings s;
    s.preset = std::string(name);
    if (name == "fast") {
        // Fewest fragments and taps: one spine sample, quarter-resolution bloom, thin lines.
        s.depth = DepthFormat::reversed_f32;
        s.spine_samples = 1;
        s.depth_bias = 2e-4f;
        s.line_half_width_px = 1.5f;
        s.bloom_resolution = BloomResolution::quarter;
        s.bloom_taps = 5;
        s.bloom_sigma_px = 2.0f;
        return s;
    }
    if (name == "balanced") {
        // Quarter-resolution bloom: on llvmpipe the full-screen passes cost more than finding
        // the lines (a 1280x720 game frame: 25.8 ms with half-resolution bloom, 14.7 ms with
        // quarter), and with sigma scaled to match, the glow looks the same.
        s.depth = DepthFormat::reversed_f32;
        s.spine_samples = 1;
        s.depth_bias = 2e-4f;
        s.line_half_width_px = 2.0f;
        s.bloom_resolution = BloomResolution::quarter;
        s.bloom_taps = 7;
        s.bloom_sigma_px = 1.5f;
        return s;
    }
    if (name == "high") {
        // Four spine samples filtered bilinearly (an occluder's edge next to a line is placed
        // to a fraction of a pixel) and a wider, smoother bloom.
        s.depth = DepthFormat::reversed_f32;
        s.spine_samples = 4;
        s.depth_bias = 2e-4f;
        // Full detail at every distance: the LOD's raised crease angle and simplified meshes
        // made high score below balanced against the exact reference (bench --sweep).
        s.lod = false;
        s.line_half_width_px = 2.5f;
        s.bloom_resolution = BloomResolution::half;
        s.bloom_taps = 17;
        s.bloom_sigma_px = 5.0f;
        return s;
    }
    throw UserError("unknown preset '" + std::string(name) + "' (use fast, balanced or high)");
}

}  // namespace bz::render
