#pragma once
// Turns a frame list into instanced draws: culls objects outside the view frustum, computes
// camera-relative model-view matrices in double, picks a per-instance crease threshold for
// distance LOD, and groups instances by mesh so each mesh is one instanced draw (unless
// RenderSettings::instancing is off: then every object is its own draw).
#include <vector>

#include "render/camera/camera_math.h"
#include "render/gpu_scene/mesh_cache.h"
#include "render/renderer.h"

namespace bz::render {

struct Batch {
    scene::MeshId mesh = 0;
    GLuint first_instance = 0;
    GLsizei instance_count = 0;
    bool occluder = true;
    int lod = 0;  // 1: the mesh's simplified version (MeshCache::get)
    // The eye is outside every instance's bounds: for an outward-closed mesh (GpuMesh) back
    // faces are then hidden by the mesh itself and both passes may skip them.
    bool eye_outside = false;
};

struct FrameBatches {
    std::vector<InstanceData> instances;
    std::vector<Batch> batches;
    // Per item of the frame list, its index in `instances`; kNotDrawn when culled or skipped.
    std::vector<std::uint32_t> instance_of_item;
    static constexpr std::uint32_t kNotDrawn = ~0u;
    FrameStats stats;
};

FrameBatches build_batches(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                           const CameraMatrices& cam, const RenderSettings& settings,
                           int viewport_height);

// The crease threshold an object gets at a projected radius of `radius_px` pixels: far
// objects keep only their strongest creases, tiny ones only silhouettes (Bernardoni 2018: far
// models look cramped with constant-width lines).
float lod_cos_crease(const RenderSettings& settings, double radius_px);
// The mesh detail an object gets at that projected radius: 0 full, 1 simplified.
int lod_level(const RenderSettings& settings, double radius_px);

// Whether a batch draws its mesh's material boundaries: when the settings ask, the mesh has
// some, and the batch is at full detail (a simplified mesh has one material, so far objects
// draw none whichever mesh they get; the reference mirrors this rule).
bool material_lines_for(const RenderSettings& settings, const Batch& batch, const GpuMesh& mesh);

}  // namespace bz::render
