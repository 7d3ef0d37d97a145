#include "render/lines/edge_culling.h"

#include <algorithm>
#include <array>

namespace bz::render {

namespace {

// The lateral guard band of shaders/lines/edge_geometry.glsl (kGuard): |x|, |y| <= 2 w.
constexpr double kGuard = 2.0;

enum class GroupVerdict {
    test_clusters,  // its clusters are tested one by one
    outside,        // every cluster outside the guard band
    facing_away,    // every face away, and the frame skips back faces
    one_way,        // every face one way, and no crease candidate below the threshold
};

GroupVerdict judge_group(const geo::EdgeClusterGroup& group, const InstanceClusters& instance,
                         const ViewVolume& guard, bool inside, float cos_crease,
                         bool skip_back_faces) {
    if (!inside && instance.outside(group, guard)) return GroupVerdict::outside;
    switch (instance.facing(group)) {
        case ClusterFacing::mixed:
            return GroupVerdict::test_clusters;
        case ClusterFacing::all_back:
            if (skip_back_faces) return GroupVerdict::facing_away;
            break;
        case ClusterFacing::all_front:
            break;
    }
    // Its clusters' crease prefixes are all empty: crease_prefix counts keys below cos_crease.
    return group.min_key < cos_crease ? GroupVerdict::test_clusters : GroupVerdict::one_way;
}

}  // namespace

void append_edge_work(const geo::ClusteredEdges& clusters, const glm::mat4& model_view,
                      float cos_crease, bool skip_back_faces, const CullView& view,
                      std::uint32_t instance, std::vector<EdgeWorkItem>& work, EdgeCullStats& stats,
                      const EdgeWorkOptions& options) {
    const HizView* hiz = options.hiz;
    std::vector<HizBounds>* bounds = options.bounds;
    const EdgeFacingTable* prefilter = options.prefilter;
    const ViewVolume guard(view.proj, view.near, view.far, kGuard);
    const InstanceClusters instance_view(model_view);
    // An instance wholly inside the view needs no test per cluster.
    const bool inside = instance_view.inside(clusters.all, guard);
    const glm::vec3 eye(object_space_eye(model_view));  // as edges.comp gets it
    const std::size_t end = std::min(options.end_cluster, clusters.clusters.size());
    for (std::size_t i = options.first_cluster; i < end; ++i) {
        // A group wholly in range is judged first; when that settles all its clusters, they
        // are counted as their own tests would have counted them, and skipped.
        const std::size_t g = i / geo::kClustersPerGroup;
        const std::size_t group_end =
            std::min(clusters.clusters.size(), (g + 1) * geo::kClustersPerGroup);
        if (i % geo::kClustersPerGroup == 0 && g < clusters.groups.size() && group_end <= end) {
            const GroupVerdict verdict = judge_group(clusters.groups[g], instance_view, guard,
                                                     inside, cos_crease, skip_back_faces);
            if (verdict != GroupVerdict::test_clusters) {
                ++stats.groups_settled;
                for (std::size_t c = i; c < group_end; ++c) {
                    const geo::EdgeCluster& k = clusters.clusters[c];
                    ++stats.clusters;
                    stats.edges += k.count;
                    if (k.candidates == 0) continue;
                    switch (verdict) {
                        case GroupVerdict::outside:
                            ++stats.outside_frustum;
                            break;
                        case GroupVerdict::facing_away:
                            ++stats.facing_away;
                            break;
                        case GroupVerdict::one_way:
                            ++stats.one_way;
                            break;
                        case GroupVerdict::test_clusters:
                            break;
                    }
                }
                i = group_end - 1;
                continue;
            }
        }
        const geo::EdgeCluster& k = clusters.clusters[i];
        ++stats.clusters;
        stats.edges += k.count;
        if (k.candidates == 0) continue;  // flat edges only: never a feature edge
        if (!inside && instance_view.outside(k, guard)) {
            ++stats.outside_frustum;
            continue;
        }
        std::uint32_t count = k.candidates;
        switch (instance_view.facing(k)) {
            case ClusterFacing::mixed:
                break;
            case ClusterFacing::all_back:
                if (skip_back_faces) {
                    ++stats.facing_away;
                    continue;
                }
                [[fallthrough]];
            case ClusterFacing::all_front:
                ++stats.one_way;
                count = geo::crease_prefix(clusters, k, cos_crease);
                break;
        }
        if (count == 0) continue;
        const auto bounds_index = static_cast<std::uint32_t>(bounds ? bounds->size() : 0);
        if (prefilter) {
            stats.edges_prefiltered += count;
            std::array<std::uint32_t, geo::kMaxClusterEdges> kept;
            const std::uint32_t listed =
                list_maybe_features(*prefilter, k.first, count, eye, cos_crease, kept.data());
            for (std::uint32_t j = 0; j < listed; ++j)
                work.push_back(EdgeWorkItem(instance, kept[j], bounds_index, j == 0 ? 1u : 0u));
            if (listed == 0) continue;
            count = listed;
        } else {
            work.push_back(EdgeWorkItem(instance, k.first, count, 0u));
        }
        stats.edges_dispatched += count;
        ++stats.items;
        if (hiz && bounds) {
            const ViewSphere sphere = instance_view.view_sphere(k);
            bounds->push_back(hiz_bounds(*hiz, glm::vec3(sphere.center),
                                         static_cast<float>(sphere.radius * (1.0 + 1e-5))));
        }
    }
}

}  // namespace bz::render
