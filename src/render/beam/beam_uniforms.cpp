#include "render/beam/beam_uniforms.h"

#include <algorithm>

namespace bz::render {

namespace {

// Widths are given on a 1080-line screen (full width); the shader wants half-widths here. On
// small targets a beam never gets narrower than 1.5 px, below which its profile aliases.
float scaled_half(float width_1080_px, int target_height) {
    return std::max(0.75f, 0.5f * width_1080_px * static_cast<float>(target_height) / 1080.0f);
}

}  // namespace

float beam_half_width_min(const BeamSettings& b, float preset_half_width_px, int target_height) {
    return b.intensity_width ? scaled_half(b.width_min_px, target_height) : preset_half_width_px;
}

float beam_half_width_max(const BeamSettings& b, float preset_half_width_px, int target_height) {
    return b.intensity_width ? scaled_half(b.width_max_px, target_height) : preset_half_width_px;
}

void set_beam_uniforms(const gl::Program& p, const BeamSettings& b, float preset_half_width_px,
                       int target_height, std::uint32_t seed, bool mask_mode) {
    if (mask_mode) {
        p.set("u_beam_width", glm::vec4(1.0f, 1.0f, 0.0f, 1.0f));
        p.set("u_beam_shape", glm::vec4(0.0f));
        p.set("u_beam_seed", 0u);
        p.set("u_beam_lengthen", 0.0f);
        return;
    }
    const float lo = beam_half_width_min(b, preset_half_width_px, target_height);
    const float hi = beam_half_width_max(b, preset_half_width_px, target_height);
    const float dwell_px = b.dwell_px * static_cast<float>(target_height) / 1080.0f;
    p.set("u_beam_width",
          glm::vec4(lo, hi, std::clamp(b.intensity_weight, -0.99f, 0.99f), b.nominal));
    p.set("u_beam_shape", glm::vec4(std::clamp(b.flicker, 0.0f, 1.0f), dwell_px,
                                    std::max(b.dwell_max, 1.0f), std::max(b.defocus, 0.0f)));
    p.set("u_beam_seed", static_cast<unsigned>(seed));
    p.set("u_beam_lengthen", std::max(b.end_lengthening, 0.0f));
}

}  // namespace bz::render
