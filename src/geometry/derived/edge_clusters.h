#pragma once
// Edge clusters: the unique edge list (edge_list.h) regrouped into small clusters of nearby
// edges whose faces point roughly one way, each with bounds that let a frame skip it before any
// per-edge work (LineMethod::compute).
//
// A silhouette edge has one face towards the eye and one away. A cluster whose faces all face
// the eye, or all face away, has no silhouette (Sander et al., "Silhouette Clipping",
// SIGGRAPH 2000, with a normal cone per cluster): a frame then tests only the cluster's crease
// and boundary candidates, which are kept first in the cluster, sorted by crease strength; and
// a closed mesh seen from outside skips a cluster that faces away entirely. A cone bounds the
// faces on the cluster's edges, including the faces across its border, so an edge on a
// cluster's border is judged by both its faces like any other.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/derived/cluster_bounds.h"
#include "geometry/derived/edge_list.h"
#include "geometry/mesh.h"

namespace bz::geo {

// At most this many edges per cluster: one compute work group (edges.comp) per cluster.
inline constexpr std::uint32_t kMaxClusterEdges = 64;

// The crease key of an edge without face B: below every threshold cosine, so such an edge (a
// feature at every view) sorts first.
inline constexpr float kAlwaysFeatureKey = -3.0f;

// The crease key of a material boundary (kEdgeMaterialBoundary): below every threshold the
// crease test uses, so it is always tested (edges.comp draws it when material lines are on,
// else only when it is a crease or a silhouette), even between coplanar faces.
inline constexpr float kMaterialKey = -2.5f;

// The crease key of an edge between coplanar faces (its cos_dihedral rounds to 1): never a
// crease, and a silhouette only when the eye lies in the faces' plane (within the float
// rounding of their normals), where the edge lies along the plane's own outline. It sorts last
// and is never tested: flat subdivision and flat quads split into triangles cost nothing.
inline constexpr float kFlatKey = 3.0f;

// The sphere and the cone (ClusterBounds) bound the candidates only.
struct EdgeCluster : ClusterBounds {
    std::uint32_t first = 0;  // its edges: [first, first + count) of ClusteredEdges::edges
    std::uint32_t count = 0;
    // The first `candidates` edges may be feature edges; the rest are flat (kFlatKey).
    std::uint32_t candidates = 0;
};

// Consecutive clusters (meshlets grow outward, so neighbours lie near) bounded together: a
// frame tests a group first and skips all its clusters when the group is outside the view,
// faces away, or faces one way without a crease candidate below the threshold, so culling
// costs per group where the silhouette is not (Sander et al.'s cone hierarchy, two levels).
inline constexpr std::uint32_t kClustersPerGroup = 16;

// Group g holds clusters [g * kClustersPerGroup, (g + 1) * kClustersPerGroup); its sphere and
// cone bound its clusters' candidates and their faces.
struct EdgeClusterGroup : ClusterBounds {
    float min_key = kFlatKey;  // the lowest crease key of its candidates
};

struct ClusteredEdges {
    std::vector<MeshEdge> edges;  // every edge of the list, cluster by cluster
    // Per edge, what the crease test compares with the instance's cos(crease angle): the
    // edge's cos_dihedral, kAlwaysFeatureKey without face B, kMaterialKey for a material
    // boundary, kFlatKey between coplanar faces,
    // 2 where the cosine is not a number. Ascending inside each cluster.
    std::vector<float> crease_keys;
    std::vector<EdgeCluster> clusters;
    std::vector<EdgeClusterGroup> groups;
    ClusterBounds all;  // a sphere around every cluster's candidates (no cone)
};

// Groups `edges` (build_edge_list(mesh)) with meshoptimizer's meshlet builder: each edge goes
// with its face A's meshlet, and a meshlet's edges are split into clusters of at most
// kMaxClusterEdges. Deterministic.
ClusteredEdges cluster_edges(const AdjacencyMesh& mesh, std::span<const MeshEdge> edges);

// Edges of the cluster that are features when no silhouette can be among them: those whose
// crease key is below `cos_crease` (a prefix of the cluster, by the sort).
std::uint32_t crease_prefix(const ClusteredEdges& c, const EdgeCluster& cluster, float cos_crease);

}  // namespace bz::geo
