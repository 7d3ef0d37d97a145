#pragma once
// The compute prepass: the depth prepass's small triangles rasterised by a compute shader
// (shaders/lines/prepass_raster.comp) instead of the GL pipeline. On llvmpipe the pipeline
// transforms, clips and sets up every triangle on one thread, and a dense mesh's triangles
// cover a pixel centre or two each, so that set-up is most of the prepass; a compute shader
// runs on every thread. Measured on Suzanne (252k triangles, 800x600, one llvmpipe thread):
// the pipeline's prepass 61.7 ms, compute 25.7 ms (docs/measurements/compute-prepass.md).
//
// Per frame, draw_batch_triangles (render/passes.h) routes each kept triangle cluster whose
// bounding sphere lies wholly beyond the near plane and covers at most kMaxRasterClusterPx
// pixels each way (RasterRoute, gpu_scene/triangle_culling.h) to a work item; the rest are
// drawn as before. The work items rasterise into Targets::raster_depth (the nearest depth's
// float bits, an atomic maximum under reversed-Z), and one rectangle over the routed clusters'
// union merges it into the depth buffer under the prepass's own depth test. What reads the
// depth afterwards sees the same surfaces, at the same pixel centres, up to float rounding.
#include <cstddef>

#include "render/passes.h"

namespace bz::render {

// A frame submitting fewer occluder triangles than its pixels / kPixelsPerRasterTriangle
// stays on the pipeline under PrepassRaster::automatic: clearing and merging the compute
// image costs per pixel of the routed rectangle, which a few triangles do not pay back. From
// the per-unit costs measured on llvmpipe, one thread: the pipeline ~240 ns per small
// triangle, compute ~90, the merge ~4.6 ns per pixel, so compute pays from about one
// triangle per 32 pixels.
inline constexpr std::size_t kPixelsPerRasterTriangle = 32;
// And below this many routed triangles the compute shader's fixed costs (the clear, the
// dispatches, the merge's draw: about 1 ms on llvmpipe) outweigh what it saves: the seed's
// hallway routes 4,492 and its prepass took 7.49 ms with them against 7.01 without (quiet,
// two threads, docs/measurements/compute-prepass.md).
inline constexpr std::size_t kMinRasterTriangles = 16384;

// Whether this frame's prepass hands its small clusters to the compute shader: with
// reversed-Z float depth and cluster culling, as RenderSettings::prepass_raster says (on
// automatic: on a software rasteriser, with enough occluder triangles for the frame's size).
bool computes_prepass(const PassContext& ctx);

// Rasterises `route`'s work items into Targets::raster_depth and merges them into the bound
// depth target with `depth_state` (the prepass's depth test). Under PrepassRaster::automatic,
// when the routed triangles number fewer than kMinRasterTriangles or than their rectangle's
// pixels / kPixelsPerRasterTriangle, the pipeline draws them instead (the prepass's program).
// Returns whether the compute shader drew them.
bool raster_routed_clusters(const PassContext& ctx, const RasterRoute& route,
                            const gl::PipelineState& depth_state);

}  // namespace bz::render
