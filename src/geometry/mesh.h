#pragma once
// Mesh data shared by import, adjacency, the renderer's mesh cache and the CPU reference.
// Positions stay in the model's own coordinates: nothing here re-centres or rescales.
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace bz::geo {

// A plain indexed triangle list, as imported or generated.
struct TriMesh {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;  // 3 per triangle, counter-clockwise = front
    // Per triangle, its material (an importer's material index); empty: one material for all.
    // Faces of different materials meet at material boundaries (material_edges.h).
    std::vector<std::uint32_t> face_materials;
    std::size_t triangle_count() const { return indices.size() / 3; }
};

// What lies across one triangle edge.
enum class EdgeKind : std::uint8_t {
    interior = 0,      // exactly one neighbour, wound consistently
    boundary = 1,      // no neighbour
    non_manifold = 2,  // three or more faces share the edge
    inconsistent = 3,  // one neighbour, wound the other way
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return (min + max) * 0.5f; }
    float radius() const { return glm::length(max - min) * 0.5f; }
};

// A welded mesh with GL_TRIANGLES_ADJACENCY indices, ready for the line pipeline.
//
// adjacency holds 6 indices per triangle: v0 a0 v1 a1 v2 a2, where a_i is the vertex opposite
// edge (v_i, v_{i+1}) in the neighbouring triangle. Edges that are not `interior` have no
// usable neighbour; for them a_i == v_i (a degenerate neighbour), which the geometry shader
// reads as "always a feature edge". edge_kinds says which kind each edge is (3 per triangle).
struct AdjacencyMesh {
    std::vector<glm::vec3> positions;      // unique after welding
    std::vector<std::uint32_t> triangles;  // 3 per triangle, into positions
    std::vector<std::uint32_t> adjacency;  // 6 per triangle
    std::vector<EdgeKind> edge_kinds;      // 3 per triangle
    // 3 per triangle: 1 where the edge is interior and the face across it has another
    // material (material_edges.h); empty when the mesh has one material. View-independent,
    // found once by build_line_mesh; drawn only when a level or command asks (material_lines).
    std::vector<std::uint8_t> material_edges;
    std::size_t triangle_count() const { return triangles.size() / 3; }
    bool has_material_edges() const { return !material_edges.empty(); }
};

// What cleaning and adjacency building found, for logs and tests.
// The *_edges counts count distinct edges: a non-manifold edge on three faces counts once,
// while each of its three triangle edges carries EdgeKind::non_manifold (see build_line_mesh).
struct MeshReport {
    std::size_t input_triangles = 0;
    std::size_t degenerate_removed = 0;
    std::size_t twins_removed = 0;
    std::size_t duplicates_removed = 0;
    std::size_t boundary_edges = 0;
    std::size_t non_manifold_edges = 0;
    std::size_t inconsistent_edges = 0;
    std::size_t welded_vertices = 0;
};

Bounds compute_bounds(const std::vector<glm::vec3>& positions);

}  // namespace bz::geo
