#pragma once
// The uniforms of shaders/beam/beam_width.glsl, from the beam settings, for any program that
// extrudes lines (scene lines, HUD lines, other line paths).
#include <cstdint>

#include "gl/program.h"
#include "render/settings.h"

namespace bz::render {

// `preset_half_width_px`: the constant half-width the look uses when the width does not
// follow intensity (the preset's line width, or 1 for the accuracy mask). `mask_mode` turns
// every beam effect off, so the mask always sees 1-pixel quads.
void set_beam_uniforms(const gl::Program& p, const BeamSettings& beam, float preset_half_width_px,
                       int target_height, std::uint32_t seed, bool mask_mode);

// The half-width range (px) the look gives lines on a target `target_height` pixels high.
float beam_half_width_min(const BeamSettings& beam, float preset_half_width_px, int target_height);
float beam_half_width_max(const BeamSettings& beam, float preset_half_width_px, int target_height);

}  // namespace bz::render
