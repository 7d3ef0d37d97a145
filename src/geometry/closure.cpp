#include "geometry/closure.h"

#include <algorithm>

namespace bz::geo {

bool is_outward_closed(const AdjacencyMesh& mesh) {
    if (mesh.triangles.empty()) return false;
    const bool watertight = std::all_of(mesh.edge_kinds.begin(), mesh.edge_kinds.end(),
                                        [](EdgeKind k) { return k == EdgeKind::interior; });
    if (!watertight) return false;
    double six_volume = 0.0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 a(mesh.positions[mesh.triangles[3 * t]]);
        const glm::dvec3 b(mesh.positions[mesh.triangles[3 * t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.triangles[3 * t + 2]]);
        six_volume += glm::dot(a, glm::cross(b, c));
    }
    return six_volume > 0.0;
}

}  // namespace bz::geo
