#include "geometry/derived/simplify.h"

#include <meshoptimizer.h>

#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {

std::optional<AdjacencyMesh> simplify_line_mesh(const AdjacencyMesh& mesh,
                                                const SimplifyOptions& o) {
    const std::size_t tris = mesh.triangle_count();
    if (tris < o.min_triangles || mesh.positions.empty()) return std::nullopt;
    const auto target = static_cast<std::size_t>(static_cast<double>(tris) * o.triangle_ratio) * 3;
    std::vector<std::uint32_t> out(mesh.triangles.size());
    const std::size_t n =
        meshopt_simplify(out.data(), mesh.triangles.data(), mesh.triangles.size(),
                         &mesh.positions[0].x, mesh.positions.size(), sizeof(glm::vec3), target,
                         o.max_error, meshopt_SimplifyLockBorder, nullptr);
    if (n == 0 || static_cast<double>(n / 3) > static_cast<double>(tris) * o.min_gain)
        return std::nullopt;
    out.resize(n);
    // meshoptimizer merges faces across material boundaries: a simplified mesh has one material.
    TriMesh reduced{mesh.positions, std::move(out), {}};
    AdjacencyMesh result = build_line_mesh(reduced);
    if (result.triangle_count() == 0) return std::nullopt;
    return result;
}

}  // namespace bz::geo
