#include "render/gpu_scene/triangle_culling.h"

namespace bz::render {

void RasterRoute::take(const RasterRoute& o) {
    work.insert(work.end(), o.work.begin(), o.work.end());
    lo = glm::min(lo, o.lo);
    hi = glm::max(hi, o.hi);
}

namespace {

// Whether `route` takes cluster `k`, and if so, its work item.
bool routed(RasterRoute& route, const InstanceClusters& instance_view,
            const geo::TriangleCluster& k, bool skip_back_faces, std::uint32_t instance) {
    // The shader holds a cluster's vertices in one work group's shared memory.
    if (k.vertex_count == 0 || k.vertex_count > geo::kClusterVertices || k.index_count > 3 * 255)
        return false;
    const ViewSphere s = instance_view.view_sphere(k);
    const std::optional<ScreenRect> rect =
        sphere_screen_rect(route.view, glm::vec3(s.center), static_cast<float>(s.radius));
    if (!rect) return false;
    const glm::vec2 size = rect->hi - rect->lo;
    if (!(size.x <= kMaxRasterClusterPx && size.y <= kMaxRasterClusterPx)) return false;
    route.work.push_back(pack(RasterItem{.instance = instance,
                                         .first_triangle = k.first_index / 3,
                                         .triangles = k.index_count / 3,
                                         .first_vertex = k.first_vertex,
                                         .vertices = k.vertex_count,
                                         .skip_back_faces = skip_back_faces}));
    route.lo = glm::min(route.lo, rect->lo);
    route.hi = glm::max(route.hi, rect->hi);
    return true;
}

// Whether p lies outside the box by more than the rounding of the object-space eye.
bool outside_box(const geo::Bounds& box, const glm::vec3& p) {
    const glm::vec3 margin =
        (box.max - box.min + glm::abs(box.min) + glm::abs(box.max) + glm::abs(p)) * 1e-5f;
    return glm::any(glm::lessThan(p, box.min - margin)) ||
           glm::any(glm::greaterThan(p, box.max + margin));
}

}  // namespace

void append_triangle_draws(const std::vector<geo::TriangleCluster>& clusters,
                           const geo::ClusterBounds& all, const glm::mat4& model_view,
                           bool skip_back_faces, const ViewVolume& view, std::uint32_t instance,
                           std::vector<TriangleDraw>& draws, TriangleCullStats& stats,
                           RasterRoute* route, std::vector<TriangleDraw>* one_sided) {
    const InstanceClusters instance_view(model_view);
    // An instance wholly inside the view needs no test per cluster.
    const bool inside = instance_view.inside(all, view);
    // Closed pieces' back faces may go where the batch keeps both faces, unless the instance
    // mirrors (its front faces would then wind the other way on screen).
    const glm::vec4 eye = object_space_eye(model_view);
    const bool pieces = one_sided && !skip_back_faces && eye.w > 0.0f;
    // The last draw of each list ends where this cluster begins.
    bool extend = false, extend_one_sided = false;
    for (const geo::TriangleCluster& k : clusters) {
        ++stats.clusters;
        stats.triangles += k.index_count / 3;
        const bool closed = pieces && k.closed && outside_box(k.closed_box, glm::vec3(eye));
        bool keep = true;
        if (!inside && instance_view.outside(k, view)) {
            ++stats.outside_frustum;
            keep = false;
        } else if ((skip_back_faces || closed) &&
                   instance_view.facing(k) == ClusterFacing::all_back) {
            ++stats.facing_away;
            keep = false;
        }
        if (!keep) {
            extend = extend_one_sided = false;
            continue;
        }
        stats.triangles_drawn += k.index_count / 3;
        if (route && routed(*route, instance_view, k, skip_back_faces || closed, instance)) {
            stats.triangles_computed += k.index_count / 3;
            extend = extend_one_sided = false;
            continue;
        }
        std::vector<TriangleDraw>& list = closed ? *one_sided : draws;
        bool& extends = closed ? extend_one_sided : extend;
        if (closed) ++stats.one_sided;
        if (extends && list.back().first_index + list.back().count == k.first_index) {
            list.back().count += k.index_count;
        } else {
            list.push_back({k.index_count, 1, k.first_index, 0, instance});
            extends = true;
        }
        (closed ? extend : extend_one_sided) = false;
    }
}

}  // namespace bz::render
