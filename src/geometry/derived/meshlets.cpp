#include "geometry/derived/meshlets.h"

namespace bz::geo {

Meshlets build_meshlets(const AdjacencyMesh& mesh, std::size_t max_vertices,
                        std::size_t max_triangles, float cone_weight) {
    return build_meshlets(mesh, mesh.triangles, max_vertices, max_triangles, cone_weight);
}

Meshlets build_meshlets(const AdjacencyMesh& mesh, std::span<const std::uint32_t> indices,
                        std::size_t max_vertices, std::size_t max_triangles, float cone_weight) {
    Meshlets out;
    if (indices.empty() || mesh.positions.empty()) return out;
    const std::size_t bound =
        meshopt_buildMeshletsBound(indices.size(), max_vertices, max_triangles);
    out.meshlets.resize(bound);
    out.vertices.resize(bound * max_vertices);
    out.local.resize(bound * max_triangles * 3);
    out.meshlets.resize(meshopt_buildMeshlets(
        out.meshlets.data(), out.vertices.data(), out.local.data(), indices.data(), indices.size(),
        &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3), max_vertices, max_triangles,
        cone_weight));
    return out;
}

}  // namespace bz::geo
