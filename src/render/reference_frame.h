#pragma once
// The CPU reference (geometry/reference.h) for a whole frame list: the same camera, the same
// occluder flags and line style the renderer uses, at full detail.
#include <cstdint>
#include <vector>

#include "geometry/reference/reference.h"
#include "render/settings.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::render {

struct ReferenceFrameOptions {
    double crease_angle_deg = 60.0;
    // Mirror the renderer's distance LOD crease threshold (lod_cos_crease) instead of using
    // the full-detail crease angle everywhere. Off for the exact reference.
    bool mirror_lod_creases = false;
    // Material boundaries are lines too (RenderSettings::material_lines); with
    // mirror_lod_creases, only on objects the renderer draws at full detail (material_lines_for).
    bool material_lines = false;
    // Intersection lines too (RenderSettings::intersection_lines); with mirror_lod_creases,
    // only between objects the renderer draws at full detail (intersection_records.h).
    bool intersection_lines = false;
    geo::ReferenceOptions sampling;
};

// The frame's visible line segments (geo::reference_segments); `instance` indexes
// frame.items.
std::vector<geo::VisibleSegment> reference_frame_segments(const scene::FrameList& frame,
                                                          const scene::MeshLibrary& meshes,
                                                          int width, int height,
                                                          const ReferenceFrameOptions& options = {},
                                                          geo::ReferenceStats* stats = nullptr);

std::vector<std::uint8_t> reference_frame_mask(const scene::FrameList& frame,
                                               const scene::MeshLibrary& meshes, int width,
                                               int height,
                                               const ReferenceFrameOptions& options = {},
                                               geo::ReferenceStats* stats = nullptr);

}  // namespace bz::render
