#include "geometry/derived/dihedral.h"

#include <glm/glm.hpp>

namespace bz::geo {

namespace {

glm::dvec3 unit_normal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

}  // namespace

std::vector<float> edge_dihedral_cosines(const AdjacencyMesh& mesh) {
    const std::size_t tris = mesh.triangle_count();
    std::vector<float> out(tris * 3, 2.0f);
    auto pos = [&](std::uint32_t i) { return glm::dvec3(mesh.positions[i]); };
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* adj = &mesh.adjacency[t * 6];
        const glm::dvec3 n = unit_normal(pos(adj[0]), pos(adj[2]), pos(adj[4]));
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t v0 = adj[2 * e], across = adj[2 * e + 1], v1 = adj[(2 * e + 2) % 6];
            if (mesh.edge_kinds[t * 3 + static_cast<std::size_t>(e)] != EdgeKind::interior)
                continue;
            const glm::dvec3 m = unit_normal(pos(v0), pos(across), pos(v1));
            out[t * 3 + static_cast<std::size_t>(e)] = static_cast<float>(glm::dot(n, m));
        }
    }
    return out;
}

}  // namespace bz::geo
