#pragma once
// Bounds of a cluster of faces, for culling it whole before per-element work: a sphere around
// its vertices and a cone around its faces' unit normals. Edge clusters (edge_clusters.h) and
// triangle clusters (triangle_clusters.h) both use them, and render/gpu_scene/cluster_culling.h
// tests them against a view.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

struct ClusterBounds {
    glm::vec3 center{0.0f};  // a sphere around every vertex of the cluster
    float radius = 0.0f;
    glm::vec3 axis{0.0f};  // unit axis of the cone around its faces' unit normals
    // Cosine of the cone's half-angle, already widened for rounding; -1 when the faces have no
    // usable cone (a degenerate face, or normals spread over a half-space): never culled by
    // facing.
    float cos_spread = -1.0f;
};

// A triangle's unit normal in double (by its winding); nullopt when it is degenerate: its
// float normal may then round to zero or turn, so no cone may rely on it.
std::optional<glm::dvec3> unit_normal(const AdjacencyMesh& mesh, std::uint32_t a, std::uint32_t b,
                                      std::uint32_t c);

// Every triangle's unit_normal, in triangle order.
std::vector<std::optional<glm::dvec3>> unit_face_normals(const AdjacencyMesh& mesh);

// The sphere around `vertices` and the cone around `normals` (no cone if one is missing).
// Empty `vertices`: a zero sphere, no cone.
ClusterBounds bound_faces(const AdjacencyMesh& mesh, std::span<const std::uint32_t> vertices,
                          std::span<const std::optional<glm::dvec3>> normals);

}  // namespace bz::geo
