#pragma once
// meshoptimizer's meshlet builder on a welded mesh, with its output buffers owned: the one
// place edge clusters and triangle clusters split a mesh into meshlets.
#include <meshoptimizer.h>

#include <cstdint>
#include <span>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

struct Meshlets {
    std::vector<meshopt_Meshlet> meshlets;
    std::vector<unsigned int> vertices;  // each meshlet's vertices, from vertex_offset
    std::vector<unsigned char> local;    // each meshlet's triangles as 3 indices into those
    // The mesh vertex of corner `corner` (0-2) of meshlet `m`'s triangle `t`.
    std::uint32_t vertex(const meshopt_Meshlet& m, std::size_t t, int corner) const {
        return vertices[m.vertex_offset + local[m.triangle_offset + 3 * t + corner]];
    }
};

// The weight both cluster kinds give meshoptimizer for tight normal cones against compact
// meshlets: back-facing clusters are what culling skips.
inline constexpr float kMeshletConeWeight = 0.5f;

// At most `max_vertices` and `max_triangles` (a multiple of 4) per meshlet; `cone_weight`
// trades compact meshlets against tight normal cones. Deterministic; empty for an empty mesh.
Meshlets build_meshlets(const AdjacencyMesh& mesh, std::size_t max_vertices,
                        std::size_t max_triangles, float cone_weight);
// The same for the triangles `indices` lists (3 per triangle, into mesh.positions).
Meshlets build_meshlets(const AdjacencyMesh& mesh, std::span<const std::uint32_t> indices,
                        std::size_t max_vertices, std::size_t max_triangles, float cone_weight);

}  // namespace bz::geo
