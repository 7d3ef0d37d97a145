#include "render/gpu_scene/triangle_culling.h"

namespace bz::render {

void append_triangle_draws(const std::vector<geo::TriangleCluster>& clusters,
                           const geo::ClusterBounds& all, const glm::mat4& model_view,
                           bool skip_back_faces, const ViewVolume& view, std::uint32_t instance,
                           std::vector<TriangleDraw>& draws, TriangleCullStats& stats) {
    const InstanceClusters instance_view(model_view);
    // An instance wholly inside the view needs no test per cluster.
    const bool inside = instance_view.inside(all, view);
    bool extend = false;  // the last draw ends where this cluster begins
    for (const geo::TriangleCluster& k : clusters) {
        ++stats.clusters;
        stats.triangles += k.index_count / 3;
        bool keep = true;
        if (!inside && instance_view.outside(k, view)) {
            ++stats.outside_frustum;
            keep = false;
        } else if (skip_back_faces && instance_view.facing(k) == ClusterFacing::all_back) {
            ++stats.facing_away;
            keep = false;
        }
        if (!keep) {
            extend = false;
            continue;
        }
        stats.triangles_drawn += k.index_count / 3;
        if (extend && draws.back().first_index + draws.back().count == k.first_index) {
            draws.back().count += k.index_count;
        } else {
            draws.push_back({k.index_count, 1, k.first_index, 0, instance});
            extend = true;
        }
    }
}

}  // namespace bz::render
