#include "render/gpu_scene/cluster_culling.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

namespace {

// Relative margin of the facing bound, far above the float rounding of a shader's test
// (normals, eye and vertex in float): a cluster that close to grazing is tested per element.
constexpr double kFacingMargin = 1e-4;

glm::dvec4 row(const glm::mat4& m, int i) {
    return glm::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]);
}

}  // namespace

double max_axis_scale(const glm::dmat3& m) {
    return std::sqrt(std::max({glm::dot(m[0], m[0]), glm::dot(m[1], m[1]), glm::dot(m[2], m[2])}));
}

glm::vec4 object_space_eye(const glm::mat4& model_view) {
    const glm::dmat4 mv(model_view);
    const double det = glm::determinant(glm::dmat3(mv));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return glm::vec4(0.0f);
    const glm::dvec3 eye(glm::inverse(mv) * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    return glm::vec4(glm::vec3(eye), det > 0.0 ? 1.0f : -1.0f);
}

ViewVolume::ViewVolume(const glm::mat4& proj, float near, float far, double guard)
    : near_(near), far_(far) {
    const glm::dvec4 w = row(proj, 3);
    for (int axis = 0; axis < 2; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const glm::dvec4 p = guard * w + (side == 0 ? -1.0 : 1.0) * row(proj, axis);
            const double l = glm::length(glm::dvec3(p));
            planes_[axis * 2 + side] = l > 0.0 ? p / l : glm::dvec4(0.0, 0.0, 0.0, 1.0);
        }
    }
}

bool ViewVolume::outside(const glm::dvec3& c, double r) const {
    const double depth = -c.z;
    if (depth + r < near_ || depth - r > far_) return true;
    for (const glm::dvec4& p : planes_)
        if (glm::dot(glm::dvec3(p), c) + p.w < -r) return true;
    return false;
}

bool ViewVolume::contains(const glm::dvec3& c, double r) const {
    const double depth = -c.z;
    if (depth - r < near_ || depth + r > far_) return false;
    for (const glm::dvec4& p : planes_)
        if (glm::dot(glm::dvec3(p), c) + p.w < r) return false;
    return true;
}

InstanceClusters::InstanceClusters(const glm::mat4& model_view)
    : model_view_(model_view), scale_(max_axis_scale(glm::dmat3(model_view_))) {
    const glm::vec4 eye = object_space_eye(model_view);
    eye_ = glm::dvec3(eye);
    eye_sign_ = eye.w;
}

ViewSphere InstanceClusters::view_sphere(const geo::ClusterBounds& k) const {
    return {.center = glm::dvec3(model_view_ * glm::dvec4(glm::dvec3(k.center), 1.0)),
            .radius = static_cast<double>(k.radius) * scale_ * (1.0 + 1e-6)};
}

bool InstanceClusters::outside(const geo::ClusterBounds& k, const ViewVolume& volume) const {
    const ViewSphere s = view_sphere(k);
    return volume.outside(s.center, s.radius);
}

bool InstanceClusters::inside(const geo::ClusterBounds& k, const ViewVolume& volume) const {
    const ViewSphere s = view_sphere(k);
    return volume.contains(s.center, s.radius);
}

// For a face with unit normal u through p: dot(u, e - p) = dot(u, e - c) + dot(u, c - p), the
// last term within +-r; the first lies between |e - c| cos(beta + alpha) and
// |e - c| cos(beta - alpha), beta the angle between the axis and e - c, alpha the cone's
// half-angle.
ClusterFacing InstanceClusters::facing(const geo::ClusterBounds& k) const {
    if (!(k.cos_spread > 0.0f) || eye_sign_ == 0.0) return ClusterFacing::mixed;
    const glm::dvec3 v = eye_ - glm::dvec3(k.center);
    const double dist = glm::length(v), r = k.radius;
    if (!(dist > r) || !std::isfinite(dist)) return ClusterFacing::mixed;
    const double cos_b = std::clamp(glm::dot(glm::dvec3(k.axis), v) / dist, -1.0, 1.0);
    const double sin_b = std::sqrt(std::max(0.0, 1.0 - cos_b * cos_b));
    const double cos_a = k.cos_spread, sin_a = std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a));
    const double lowest = cos_b < -cos_a ? -1.0 : cos_b * cos_a - sin_b * sin_a;
    const double highest = cos_b > cos_a ? 1.0 : cos_b * cos_a + sin_b * sin_a;
    const double margin = kFacingMargin * (dist + r);
    const bool all_positive = dist * lowest - r > margin;
    const bool all_negative = dist * highest + r < -margin;
    if (all_positive) return eye_sign_ > 0.0 ? ClusterFacing::all_front : ClusterFacing::all_back;
    if (all_negative) return eye_sign_ > 0.0 ? ClusterFacing::all_back : ClusterFacing::all_front;
    return ClusterFacing::mixed;
}

}  // namespace bz::render
