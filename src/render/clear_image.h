#pragma once
#include <glm/vec4.hpp>

#include "gl/texture.h"
#include "render/settings.h"

namespace bz::render {

struct PassContext;

// Clearing the frame's full-screen colour images (the lines image, the output, the canvases).
// On a software rasteriser glClear is a fill that each bin does as it starts, nearly free; on
// a GPU whose raster back end is small for its memory and shader cores (the H100, a compute
// accelerator, has a few ROPs) a 1920x1080 RGBA16F clear took 0.29 ms there, and a compute
// shader writing the same texels 0.01 (docs/measurements/clears.md). ColourClears chooses.

// Whether colour clears run as a compute shader under `settings` on this rasteriser.
bool clears_by_compute(const RenderSettings& settings, bool software_rasteriser);

// Sets every texel of `image` to `value`. `image` must be the colour attachment of the bound
// draw framebuffer (the pipeline path clears that framebuffer's colour buffers); set no scissor
// before. The compute path changes the current program: clear before using the pass's own.
void clear_colour(const PassContext& ctx, const gl::Texture2D& image, glm::vec4 value);

}  // namespace bz::render
