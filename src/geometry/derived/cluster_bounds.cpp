#include "geometry/derived/cluster_bounds.h"

#include <algorithm>
#include <cmath>

namespace bz::geo {

namespace {

// The cone's half-angle is widened by this much of its cosine, for the rounding of the float
// normals a shader compares (the culling test also keeps a margin:
// render/gpu_scene/cluster_culling.cpp).
constexpr double kConeSlack = 1e-5;

}  // namespace

std::optional<glm::dvec3> unit_normal(const AdjacencyMesh& mesh, std::uint32_t a, std::uint32_t b,
                                      std::uint32_t c) {
    const glm::dvec3 p0(mesh.positions[a]);
    const glm::dvec3 n =
        glm::cross(glm::dvec3(mesh.positions[b]) - p0, glm::dvec3(mesh.positions[c]) - p0);
    const double l = glm::length(n);
    if (!(l > 1e-30) || !std::isfinite(l)) return std::nullopt;
    return n / l;
}

std::vector<std::optional<glm::dvec3>> unit_face_normals(const AdjacencyMesh& mesh) {
    std::vector<std::optional<glm::dvec3>> out(mesh.triangle_count());
    for (std::size_t t = 0; t < out.size(); ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        out[t] = unit_normal(mesh, v[0], v[1], v[2]);
    }
    return out;
}

ClusterBounds bound_faces(const AdjacencyMesh& mesh, std::span<const std::uint32_t> vertices,
                          std::span<const std::optional<glm::dvec3>> normals) {
    ClusterBounds out;
    if (vertices.empty()) return out;
    glm::dvec3 lo(INFINITY), hi(-INFINITY), sum(0.0);
    for (const std::uint32_t v : vertices) {
        lo = glm::min(lo, glm::dvec3(mesh.positions[v]));
        hi = glm::max(hi, glm::dvec3(mesh.positions[v]));
    }
    const glm::dvec3 centre = (lo + hi) * 0.5;
    double radius = 0.0;
    for (const std::uint32_t v : vertices)
        radius = std::max(radius, glm::length(glm::dvec3(mesh.positions[v]) - centre));
    out.center = glm::vec3(centre);
    // Widened for the centre's rounding to float.
    out.radius = static_cast<float>(radius * (1.0 + 1e-6) +
                                    glm::length(glm::dvec3(out.center) - centre) + 1e-30);
    for (const std::optional<glm::dvec3>& n : normals) {
        if (!n) return out;
        sum += *n;
    }
    const double length = glm::length(sum);
    if (!(length > 1e-9)) return out;
    const glm::dvec3 axis = sum / length;
    double spread = 1.0;
    for (const std::optional<glm::dvec3>& n : normals)
        spread = std::min(spread, glm::dot(axis, *n));
    spread -= kConeSlack;
    if (spread <= 0.0) return out;  // over a half-space: no view sees all of it one way
    out.axis = glm::vec3(axis);
    out.cos_spread = static_cast<float>(spread);
    return out;
}

}  // namespace bz::geo
