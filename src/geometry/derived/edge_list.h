#pragma once
// The unique edge list of a welded mesh, for edge extraction in a compute shader
// (LineMethod::compute): one entry per edge that some frame could draw, with everything about
// it that does not depend on the view, so the per-frame work is one invocation per edge.
//
// The entries reproduce the geometry shader's emission exactly (shaders/lines/lines.geom):
//  - an interior edge (two consistently wound faces) is one entry, oriented from its lower to
//    its higher welded vertex; face A is the face that walks it that way, face B the other;
//  - every other triangle edge (boundary, non-manifold, inconsistently wound) is one entry per
//    triangle edge, in that triangle's winding, with no face B: the geometry shader emits such
//    an edge once for each face on it, and so does the compute path.
#include <cstdint>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

inline constexpr std::uint32_t kNoVertex = 0xFFFFFFFFu;

// MeshEdge::flags
inline constexpr std::uint32_t kEdgeInterior = 0u;
inline constexpr std::uint32_t kEdgeBoundary = 1u;
inline constexpr std::uint32_t kEdgeNonManifold = 2u;
inline constexpr std::uint32_t kEdgeInconsistent = 3u;
inline constexpr std::uint32_t kEdgeKindMask = 0xFu;  // the kinds above; flag bits follow
// An interior edge between faces of different materials (AdjacencyMesh::material_edges).
inline constexpr std::uint32_t kEdgeMaterialBoundary = 1u << 4;

// 36 bytes, the std430 layout of shaders/lines/edges.comp's MeshEdge.
struct MeshEdge {
    std::uint32_t a = 0, b = 0;       // the edge, in face A's winding
    std::uint32_t opp_a = 0;          // face A's third vertex
    std::uint32_t opp_b = kNoVertex;  // face B's third vertex; kNoVertex when there is no face B
    float cos_dihedral = 2.0f;        // unit normals' dot (double, object space); 2 without face B
    std::uint32_t flags = kEdgeInterior;  // kEdge* (the EdgeKind of the triangle edge), and
                                          // kEdgeMaterialBoundary
    std::uint32_t face_a = 0;             // face A's triangle (index into face_normals)
    std::uint32_t face_b = kNoVertex;     // face B's triangle; kNoVertex without face B
    // The edge's place in build_edge_list's order: stable however the list is regrouped
    // (edge_clusters.h), so per-edge seeds (sketch jitter, flicker) do not change with it.
    std::uint32_t id = 0;
};
static_assert(sizeof(MeshEdge) == 36);

// Deterministic: triangles in order, each triangle's edges in order.
std::vector<MeshEdge> build_edge_list(const AdjacencyMesh& mesh);

// Per triangle, its unnormalised normal in object space, cross(p1 - p0, p2 - p0) (the winding's
// normal, as the line shaders compute it), computed in double; w is 0 (vec4 for std430). An eye
// at E sees the front of the face when dot(normal, E - p) > 0 for a vertex p of it: testing
// against a vertex, not a stored plane offset, keeps the precision of a model far from its
// origin.
std::vector<glm::vec4> face_normals(const AdjacencyMesh& mesh);

// Unit angle-weighted vertex normals (zero for a vertex of degenerate faces only), for the edge
// buffer's smoothing data.
std::vector<glm::vec3> vertex_normals(const AdjacencyMesh& mesh);

}  // namespace bz::geo
