#pragma once
// Triangle clusters: a mesh's triangle list reordered cluster by cluster (meshoptimizer's
// meshlets), each cluster with a sphere and a normal cone (cluster_bounds.h), so a depth or
// fill pass can skip a cluster outside the view, or, for a closed mesh seen from outside, one
// whose faces all face away, before any of its vertices is shaded.
#include <cstdint>
#include <vector>

#include "geometry/derived/closure.h"
#include "geometry/derived/cluster_bounds.h"
#include "geometry/mesh.h"

namespace bz::geo {

struct TriangleCluster : ClusterBounds {
    std::uint32_t first_index = 0;  // its triangles: [first_index, first_index + index_count)
    std::uint32_t index_count = 0;  // of ClusteredTriangles::indices, 3 per triangle
    // Its distinct vertices: [first_vertex, first_vertex + vertex_count) of
    // ClusteredTriangles::vertices (at most kClusterVertices; 0: no list, the one-cluster
    // fallback).
    std::uint32_t first_vertex = 0;
    std::uint32_t vertex_count = 0;
    // Every triangle lies in an outward-closed piece (closure.h: connected_pieces): from
    // outside `closed_box`, the union of those pieces' boxes, its back faces are hidden by
    // their own pieces and need not be drawn.
    bool closed = false;
    Bounds closed_box{};
};

// The most vertices a cluster's list holds (meshoptimizer's meshlet limit).
inline constexpr std::uint32_t kClusterVertices = 64;

struct ClusteredTriangles {
    // Every triangle of the mesh exactly once, with its winding, cluster by cluster.
    std::vector<std::uint32_t> indices;
    std::vector<TriangleCluster> clusters;
    // Each cluster's distinct vertices, cluster by cluster, and per triangle (in `indices`'
    // order) its corners as indices into its cluster's list: a | b << 8 | c << 16. A pass that
    // works a cluster at a time shades each vertex once (the compute prepass).
    std::vector<std::uint32_t> vertices;
    std::vector<std::uint32_t> corners;
    ClusterBounds all;  // a sphere around every triangle (no cone)
};

// Deterministic. A mesh meshoptimizer cannot split whole comes back as one cluster in the
// original order, with no cone and a sphere around all of it (never culled by facing).
ClusteredTriangles cluster_triangles(const AdjacencyMesh& mesh);
// The same with the mesh's pieces (closure.h: connected_pieces), where the caller has them.
ClusteredTriangles cluster_triangles(const AdjacencyMesh& mesh, const Pieces& pieces);

}  // namespace bz::geo
