#pragma once
// Culling before per-edge work (LineMethod::compute): a frame turns each instance's edge
// clusters (geometry/derived/edge_clusters.h) into work items for edges.comp, one work group
// per item, and drops what cannot give a feature edge:
//  - a cluster outside the frustum's guard band (shaders/lines/edge_geometry.glsl clips every
//    edge to it, so nothing of such a cluster would be drawn or counted);
//  - the silhouette candidates of a cluster whose faces all face the eye or all face away:
//    only its crease and boundary candidates (a prefix of the cluster) are tested;
//  - all of a cluster facing away, for a closed mesh seen from outside (skip_back_faces).
// Facing is tested in object space against the eye brought into the instance's space once,
// as edges.comp does per edge, so no vertex is transformed for the test.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/derived/edge_clusters.h"
#include "render/gpu_scene/cluster_culling.h"
#include "render/lines/edge_prefilter.h"
#include "render/lines/hiz_culling.h"

namespace bz::render {

// One work group of edges.comp: x the instance, y the first edge (into the clustered edge
// list), z the number of edges (<= geo::kMaxClusterEdges), w unused. Listed (with an
// EdgeFacingTable, on a software rasteriser): one edge per entry, x the instance, y the edge,
// z its cluster's index among the chunk's hierarchical-Z bounds records, w 1 on its cluster's
// first entry.
using EdgeWorkItem = glm::uvec4;

// Invocations per work group of edges.comp (its EDGE_GROUP_SIZE), each looping over its item's
// edges. llvmpipe pays a start-up per invocation and per group whatever the invocation does:
// on Suzanne (1,733 items, 800x600) an edges.comp that returned at once took 6.2 ms with 64
// invocations per item, and 0.6 ms with 8 per group. Eight is one of its SIMD vectors; a GPU
// keeps a wide group, one edge per invocation.
constexpr unsigned edge_group_size(bool software_rasteriser) {
    return software_rasteriser ? 8u : 64u;
}

struct EdgeCullStats {
    std::size_t clusters = 0;           // (instance, cluster) pairs looked at
    std::size_t outside_frustum = 0;    // dropped whole: outside the guard band
    std::size_t facing_away = 0;        // dropped whole: closed mesh, every face away
    std::size_t one_way = 0;            // only the crease and boundary candidates tested
    std::size_t edges = 0;              // edges of the clusters looked at
    std::size_t edges_dispatched = 0;   // edges given to edges.comp
    std::size_t edges_prefiltered = 0;  // of the clusters' edges, those the CPU tested first
    std::size_t groups_settled = 0;     // cluster groups whose clusters needed no test of their own
    std::size_t items = 0;              // work items (clusters or their prefixes) given to it
    EdgeCullStats& operator+=(const EdgeCullStats& o) {
        clusters += o.clusters;
        outside_frustum += o.outside_frustum;
        facing_away += o.facing_away;
        one_way += o.one_way;
        edges += o.edges;
        edges_dispatched += o.edges_dispatched;
        edges_prefiltered += o.edges_prefiltered;
        groups_settled += o.groups_settled;
        items += o.items;
        return *this;
    }
};

// What culling needs of the view: the projection (any, perspective or not) and the depth
// range edges are clipped to.
struct CullView {
    glm::mat4 proj{1.0f};
    float near = 0.1f;
    float far = 1000.0f;
};

// What else a caller may ask of append_edge_work.
struct EdgeWorkOptions {
    // With both: each item's hierarchical-Z bounds record (hiz_culling.h), one per item.
    const HizView* hiz = nullptr;
    std::vector<HizBounds>* bounds = nullptr;
    // The mesh's table (edge_prefilter.h): list each edge of the items that may be a feature
    // edge instead of the items.
    const EdgeFacingTable* prefilter = nullptr;
    // Only these clusters (a big instance's clusters are shared among threads).
    std::size_t first_cluster = 0;
    std::size_t end_cluster = SIZE_MAX;
};

// Appends the work items of one instance's clusters to `work`.
void append_edge_work(const geo::ClusteredEdges& clusters, const glm::mat4& model_view,
                      float cos_crease, bool skip_back_faces, const CullView& view,
                      std::uint32_t instance, std::vector<EdgeWorkItem>& work, EdgeCullStats& stats,
                      const EdgeWorkOptions& options = {});

}  // namespace bz::render
