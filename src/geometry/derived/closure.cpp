#include "geometry/derived/closure.h"

#include <algorithm>
#include <numeric>

namespace bz::geo {

namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

}  // namespace

bool is_outward_closed(const AdjacencyMesh& mesh) {
    if (mesh.triangles.empty()) return false;
    const bool watertight = std::all_of(mesh.edge_kinds.begin(), mesh.edge_kinds.end(),
                                        [](EdgeKind k) { return k == EdgeKind::interior; });
    if (!watertight) return false;
    // Every connected piece must enclose a positive volume on its own: a model made of many
    // closed solids (a building's walls, slabs and rafters) may have one wound inside out, and
    // a positive total would let the prepass cull that piece's outside and show what it hides.
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t i = 0; i < mesh.triangles.size(); i += 3) {
        const std::uint32_t a = find_root(parent, mesh.triangles[i]);
        parent[find_root(parent, mesh.triangles[i + 1])] = a;
        parent[find_root(parent, mesh.triangles[i + 2])] = a;
    }
    const glm::dvec3 origin(mesh.positions[mesh.triangles[0]]);
    std::vector<double> six_volume(mesh.positions.size(), 0.0);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.triangles[3 * t]]) - origin;
        const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.triangles[3 * t + 1]]) - origin;
        const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.triangles[3 * t + 2]]) - origin;
        six_volume[find_root(parent, mesh.triangles[3 * t])] += glm::dot(a, glm::cross(b, c));
    }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        if (!(six_volume[find_root(parent, mesh.triangles[3 * t])] > 0.0)) return false;
    }
    return true;
}

}  // namespace bz::geo
