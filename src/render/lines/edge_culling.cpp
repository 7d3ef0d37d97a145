#include "render/lines/edge_culling.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

namespace {

// The lateral guard band of shaders/lines/edge_geometry.glsl (kGuard): |x|, |y| <= 2 w.
constexpr double kGuard = 2.0;
// Relative margin of the facing bound, far above the float rounding of the shader's test
// (normals, eye and vertex in float): a cluster that close to grazing is tested per edge.
constexpr double kFacingMargin = 1e-4;

glm::dvec4 row(const glm::mat4& m, int i) {
    return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]);
}

double max_axis_scale(const glm::dmat3& m) {
    return std::sqrt(std::max({glm::dot(m[0], m[0]), glm::dot(m[1], m[1]), glm::dot(m[2], m[2])}));
}

// The guard band's four side planes in view space: a point p is inside when
// dot(plane.xyz, p) + plane.w >= 0. Unit normals, so a sphere's distance reads directly.
struct GuardPlanes {
    glm::dvec4 planes[4];
    explicit GuardPlanes(const glm::mat4& proj) {
        const glm::dvec4 w = row(proj, 3);
        for (int axis = 0; axis < 2; ++axis) {
            for (int side = 0; side < 2; ++side) {
                glm::dvec4 p = kGuard * w + (side == 0 ? -1.0 : 1.0) * row(proj, axis);
                const double l = glm::length(glm::dvec3(p));
                planes[axis * 2 + side] = l > 0.0 ? p / l : glm::dvec4(0.0, 0.0, 0.0, 1.0);
            }
        }
    }
    bool outside(const glm::dvec3& c, double r) const {
        for (const glm::dvec4& p : planes)
            if (glm::dot(glm::dvec3(p), c) + p.w < -r) return true;
        return false;
    }
};

enum class Facing { mixed, all_front, all_back };

// Whether every face of the cluster (unit normals within the cone, one vertex each within
// the sphere) faces the eye, or every one faces away. For a face with unit normal u through p:
// dot(u, e - p) = dot(u, e - c) + dot(u, c - p), the last term within +-r; the first lies
// between |e - c| cos(beta + alpha) and |e - c| cos(beta - alpha), beta the angle between the
// axis and e - c, alpha the cone's half-angle.
Facing cluster_facing(const geo::EdgeCluster& k, const glm::dvec3& eye, double sign) {
    if (!(k.cos_spread > 0.0f) || sign == 0.0) return Facing::mixed;
    const glm::dvec3 v = eye - glm::dvec3(k.center);
    const double dist = glm::length(v), r = k.radius;
    if (!(dist > r) || !std::isfinite(dist)) return Facing::mixed;
    const double cos_b = std::clamp(glm::dot(glm::dvec3(k.axis), v) / dist, -1.0, 1.0);
    const double sin_b = std::sqrt(std::max(0.0, 1.0 - cos_b * cos_b));
    const double cos_a = k.cos_spread, sin_a = std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a));
    const double lowest = cos_b < -cos_a ? -1.0 : cos_b * cos_a - sin_b * sin_a;
    const double highest = cos_b > cos_a ? 1.0 : cos_b * cos_a + sin_b * sin_a;
    const double margin = kFacingMargin * (dist + r);
    const bool all_positive = dist * lowest - r > margin;
    const bool all_negative = dist * highest + r < -margin;
    if (all_positive) return sign > 0.0 ? Facing::all_front : Facing::all_back;
    if (all_negative) return sign > 0.0 ? Facing::all_back : Facing::all_front;
    return Facing::mixed;
}

}  // namespace

glm::vec4 object_space_eye(const glm::mat4& model_view) {
    const glm::dmat4 mv(model_view);
    const double det = glm::determinant(glm::dmat3(mv));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return glm::vec4(0.0f);
    const glm::dvec3 eye(glm::inverse(mv) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    return glm::vec4(glm::vec3(eye), det > 0.0 ? 1.0f : -1.0f);
}

void append_edge_work(const geo::ClusteredEdges& clusters, const glm::mat4& model_view,
                      float cos_crease, bool skip_back_faces, const CullView& view,
                      std::uint32_t instance, std::vector<EdgeWorkItem>& work,
                      EdgeCullStats& stats) {
    const glm::dmat4 mv(model_view);
    const double scale = max_axis_scale(glm::dmat3(mv));
    const GuardPlanes guard(view.proj);
    const glm::vec4 eye_sign = object_space_eye(model_view);
    const glm::dvec3 eye(eye_sign);
    for (const geo::EdgeCluster& k : clusters.clusters) {
        ++stats.clusters;
        stats.edges += k.count;
        if (k.candidates == 0) continue;  // flat edges only: never a feature edge
        const glm::dvec3 c(mv * glm::dvec4(glm::dvec3(k.center), 1.0));
        const double r = static_cast<double>(k.radius) * scale * (1.0 + 1e-6);
        const double depth = -c.z;
        if (depth + r < static_cast<double>(view.near) ||
            depth - r > static_cast<double>(view.far) || guard.outside(c, r)) {
            ++stats.outside_frustum;
            continue;
        }
        std::uint32_t count = k.candidates;
        switch (cluster_facing(k, eye, eye_sign.w)) {
            case Facing::mixed:
                break;
            case Facing::all_back:
                if (skip_back_faces) {
                    ++stats.facing_away;
                    continue;
                }
                [[fallthrough]];
            case Facing::all_front:
                ++stats.one_way;
                count = geo::crease_prefix(clusters, k, cos_crease);
                break;
        }
        if (count == 0) continue;
        stats.edges_dispatched += count;
        work.push_back(EdgeWorkItem(instance, k.first, count, 0u));
    }
}

}  // namespace bz::render
