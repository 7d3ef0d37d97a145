#include "render/reference_frame.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "render/gpu_scene/batches.h"

namespace bz::render {

namespace {

// The reference's inputs for a frame. Items whose mesh is missing get no instance but keep
// their index: `item_of` maps each instance back to its frame item.
struct FrameInstances {
    std::vector<geo::ReferenceInstance> instances;
    std::vector<std::uint32_t> item_of;
    geo::ReferenceView view;
    geo::ReferenceOptions sampling;
};

FrameInstances frame_instances(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                               int width, int height, const ReferenceFrameOptions& o) {
    FrameInstances out;
    const scene::Camera& c = frame.camera;
    const glm::dmat4 view = glm::lookAt(c.eye, c.target, c.up);
    RenderSettings lod_settings;
    lod_settings.crease_angle_deg = static_cast<float>(o.crease_angle_deg);
    lod_settings.lod = true;
    const double cot = 1.0 / std::tan(glm::radians(c.fov_y_deg) * 0.5);

    std::vector<geo::ReferenceInstance>& instances = out.instances;
    instances.reserve(frame.items.size());
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        const scene::DrawItem& item = frame.items[i];
        if (item.mesh >= meshes.size()) continue;  // the renderer skips these too
        geo::ReferenceInstance inst;
        inst.mesh = &meshes.mesh(item.mesh);
        inst.model_view = view * item.model;
        inst.occluder = item.occluder;
        inst.cos_crease = std::cos(glm::radians(o.crease_angle_deg));
        inst.material_lines = o.material_lines;
        if (o.mirror_lod_creases) {
            // Same projected radius as build_batches computes.
            const geo::Bounds& b = meshes.bounds(item.mesh);
            const glm::dvec3 centre =
                glm::dvec3(inst.model_view * glm::dvec4(glm::dvec3(b.center()), 1.0));
            const glm::dmat4& mv = inst.model_view;
            const double scale =
                std::sqrt(std::max({glm::dot(glm::dvec3(mv[0]), glm::dvec3(mv[0])),
                                    glm::dot(glm::dvec3(mv[1]), glm::dvec3(mv[1])),
                                    glm::dot(glm::dvec3(mv[2]), glm::dvec3(mv[2]))}));
            const double radius = static_cast<double>(b.radius()) * scale;
            const double depth = std::max(-centre.z, c.near);
            const double radius_px = radius * cot / depth * height * 0.5;
            inst.cos_crease = static_cast<double>(lod_cos_crease(lod_settings, radius_px));
            // Far objects get the one-material simplified mesh (material_lines_for).
            if (lod_level(lod_settings, radius_px) > 0) {
                inst.material_lines = false;
                inst.intersects = false;  // its simplified surface is in the prepass
            }
        }
        instances.push_back(inst);
        out.item_of.push_back(static_cast<std::uint32_t>(i));
    }
    geo::ReferenceView& v = out.view;
    v.width = width;
    v.height = height;
    v.fov_y_deg = c.fov_y_deg;
    v.near = c.near;
    v.far = c.far;
    out.sampling = o.sampling;
    if (o.intersection_lines) out.sampling.intersection_lines = true;
    if (frame.style == scene::LineStyle::arcade) out.sampling.occlusion = false;
    return out;
}

}  // namespace

std::vector<geo::VisibleSegment> reference_frame_segments(const scene::FrameList& frame,
                                                          const scene::MeshLibrary& meshes,
                                                          int width, int height,
                                                          const ReferenceFrameOptions& o,
                                                          geo::ReferenceStats* stats) {
    const FrameInstances in = frame_instances(frame, meshes, width, height, o);
    std::vector<geo::VisibleSegment> segments =
        geo::reference_segments(in.instances, in.view, in.sampling, stats);
    for (geo::VisibleSegment& s : segments) s.instance = in.item_of[s.instance];
    return segments;
}

std::vector<std::uint8_t> reference_frame_mask(const scene::FrameList& frame,
                                               const scene::MeshLibrary& meshes, int width,
                                               int height, const ReferenceFrameOptions& o,
                                               geo::ReferenceStats* stats) {
    const FrameInstances in = frame_instances(frame, meshes, width, height, o);
    return geo::reference_mask(in.instances, in.view, in.sampling, stats);
}

}  // namespace bz::render
