#pragma once
#include <glm/vec4.hpp>

#include "gl/program.h"
#include "gl/texture.h"
#include "render/settings.h"

namespace bz::render {

struct PassContext;

// Clearing the frame's full-screen colour images (the lines image, the output, the canvases).
// On a software rasteriser glClear is a fill that each bin does as it starts, nearly free, and
// a compute shader writing every texel costs milliseconds. On a GPU it depends on the part: a
// gaming GPU fast-clears through its raster back end, while the H100 (a compute accelerator
// with a few ROPs) took 0.29 ms to glClear a 1920x1080 RGBA16F image and 0.01 ms to write it
// from a compute shader (docs/measurements/clears.md). So ColourClears::automatic measures
// both on a hardware GPU, at the frame's size, and keeps the faster.

enum class ClearPath { pipeline, compute, measure };

// What the settings leave to do on this rasteriser: a fixed path, or to measure.
ClearPath clear_path(const RenderSettings& settings, bool software_rasteriser);

// Both ways of clearing a width x height RGBA16F image, timed on the GPU (GL_TIME_ELAPSED,
// the best of a few rounds after one to warm up). Hardware GPUs only: a software
// rasteriser's timer queries miss work (docs/measurements/line-methods.md).
struct ClearTiming {
    double pipeline_ms = 0.0;
    double compute_ms = 0.0;
    bool compute_is_faster() const { return compute_ms < pipeline_ms; }
};
ClearTiming time_colour_clears(const gl::Program& clear_image, int width, int height);

// Sets every texel of `image` to `value`, by the path PassContext::clears_by_compute names.
// `image` must be the colour attachment of the bound draw framebuffer (the pipeline path
// clears that framebuffer's colour buffers); set no scissor before. The compute path changes
// the current program: clear before using the pass's own.
void clear_colour(const PassContext& ctx, const gl::Texture2D& image, glm::vec4 value);

}  // namespace bz::render
