#include "render/gpu_scene/batches.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/gpu_scene/cluster_culling.h"

namespace bz::render {

namespace {

// Sphere (view space) against the frustum; true if entirely outside.
bool outside_frustum(const glm::dvec3& c, double r, const CameraMatrices& cam) {
    const double depth = -c.z;
    if (depth + r < cam.near || depth - r > cam.far) return true;
    const double px = cam.proj[0][0], py = cam.proj[1][1];
    const double nx = std::sqrt(px * px + 1.0), ny = std::sqrt(py * py + 1.0);
    if ((px * c.x + c.z) / nx > r || (-px * c.x + c.z) / nx > r) return true;
    if ((py * c.y + c.z) / ny > r || (-py * c.y + c.z) / ny > r) return true;
    return false;
}

// The eye (the view-space origin) in the object's own space, tested against its bounds
// grown by a relative margin. A mirroring transform turns an outward mesh inside out, so it
// never counts as outside.
bool eye_outside_bounds(const glm::dmat4& model_view, const geo::Bounds& b) {
    if (glm::determinant(glm::dmat3(model_view)) <= 0.0) return false;
    const glm::dvec3 eye = glm::dvec3(glm::inverse(model_view) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 margin = glm::dvec3(b.max - b.min) * 1e-3 + 1e-9;
    const glm::dvec3 lo = glm::dvec3(b.min) - margin, hi = glm::dvec3(b.max) + margin;
    return glm::any(glm::lessThan(eye, lo)) || glm::any(glm::greaterThan(eye, hi));
}

}  // namespace

// Below this projected radius (pixels) an object keeps only its strongest creases and is
// drawn from its simplified mesh.
constexpr double kFarRadiusPx = 40.0;

int lod_level(const RenderSettings& s, double radius_px) {
    return s.lod && radius_px < kFarRadiusPx ? 1 : 0;
}

bool material_lines_for(const RenderSettings& s, const Batch& batch, const GpuMesh& mesh) {
    return s.material_lines && mesh.has_material_edges && batch.lod == 0;
}

float lod_cos_crease(const RenderSettings& s, double radius_px) {
    double angle = s.crease_angle_deg;
    if (s.lod) {
        if (radius_px < 6.0) return -2.0f;  // below any cosine: no creases at all
        if (radius_px < kFarRadiusPx) angle = std::max(angle, 80.0);
    }
    return static_cast<float>(std::cos(glm::radians(angle)));
}

FrameBatches build_batches(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                           const CameraMatrices& cam, const RenderSettings& settings,
                           int viewport_height) {
    FrameBatches out;
    struct Visible {
        std::size_t item;
        int lod;
        bool eye_outside;
        InstanceData data;
    };
    std::vector<Visible> visible;
    visible.reserve(frame.items.size());
    for (std::size_t i = 0; i < frame.items.size(); ++i) {
        const scene::DrawItem& item = frame.items[i];
        if (item.mesh >= meshes.size()) continue;
        const glm::dmat4 mv = cam.view * item.model;
        const geo::Bounds& b = meshes.bounds(item.mesh);
        const glm::dvec3 centre = glm::dvec3(mv * glm::dvec4(glm::dvec3(b.center()), 1.0));
        const double radius = static_cast<double>(b.radius()) * max_axis_scale(glm::dmat3(mv));
        if (settings.frustum_culling && outside_frustum(centre, radius, cam)) {
            ++out.stats.objects_culled;
            continue;
        }
        const double depth = std::max(-centre.z, static_cast<double>(cam.near));
        const double radius_px = radius * cam.proj[1][1] / depth * viewport_height * 0.5;
        InstanceData d;
        d.model_view = glm::mat4(mv);
        d.color = glm::vec4(item.color * item.intensity, 1.0f);
        d.params = glm::vec4(lod_cos_crease(settings, radius_px), 0.0f, item.intensity,
                             item.smooth ? 1.0f : 0.0f);
        visible.push_back({i, lod_level(settings, radius_px), eye_outside_bounds(mv, b), d});
    }
    // Group by (mesh, lod, occluder) so each group is one instanced draw; stable keeps the
    // frame list's order inside a group, which keeps results deterministic.
    std::stable_sort(visible.begin(), visible.end(), [&](const Visible& a, const Visible& b) {
        const auto& ia = frame.items[a.item];
        const auto& ib = frame.items[b.item];
        if (ia.mesh != ib.mesh) return ia.mesh < ib.mesh;
        if (a.lod != b.lod) return a.lod < b.lod;
        if (a.eye_outside != b.eye_outside) return a.eye_outside > b.eye_outside;
        return ia.occluder > ib.occluder;
    });
    out.instances.reserve(visible.size());
    out.instance_of_item.assign(frame.items.size(), FrameBatches::kNotDrawn);
    for (const Visible& v : visible) {
        out.instance_of_item[v.item] = static_cast<std::uint32_t>(out.instances.size());
        const auto& item = frame.items[v.item];
        if (out.batches.empty() || !settings.instancing || out.batches.back().mesh != item.mesh ||
            out.batches.back().lod != v.lod || out.batches.back().occluder != item.occluder ||
            out.batches.back().eye_outside != v.eye_outside) {
            out.batches.push_back({item.mesh, static_cast<GLuint>(out.instances.size()), 0,
                                   item.occluder, v.lod, v.eye_outside});
        }
        ++out.batches.back().instance_count;
        out.instances.push_back(v.data);
        out.instances.back().params.y = static_cast<float>(out.instances.size() - 1);
        out.stats.triangles_submitted += meshes.mesh(item.mesh).triangle_count();
    }
    out.stats.objects_drawn = visible.size();
    return out;
}

}  // namespace bz::render
