#pragma once
// Edge adjacency of a welded triangle list, in the GL_TRIANGLES_ADJACENCY layout of
// AdjacencyMesh (see mesh.h).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

struct Adjacency {
    std::vector<std::uint32_t> adjacency;  // 6 per triangle: v0 a0 v1 a1 v2 a2
    std::vector<EdgeKind> edge_kinds;      // 3 per triangle
    // Counts of distinct (undirected) edges of each kind. A non-manifold edge shared by three
    // faces counts once here while all three triangle edges carry EdgeKind::non_manifold.
    std::size_t boundary_edges = 0;
    std::size_t non_manifold_edges = 0;
    std::size_t inconsistent_edges = 0;
    // True when some edge could belong to two faces with the same three vertices (duplicates
    // or back-to-back twins): an edge with 3+ faces, or two faces whose opposite vertices match.
    // False guarantees there are none, so cleaning can skip looking for them.
    bool maybe_coincident_faces = false;
};

// Builds adjacency for `triangles` (3 indices per triangle, all < vertex_count, already welded:
// equal indices mean equal positions). Expected O(n): a counting sort of the edges by their
// lower vertex. The result depends only on the input, never on memory layout.
// Throws std::invalid_argument on an out-of-range index or a size that is not a multiple of 3.
Adjacency build_adjacency(std::span<const std::uint32_t> triangles, std::size_t vertex_count);

}  // namespace bz::geo
