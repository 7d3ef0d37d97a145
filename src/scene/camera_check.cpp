#include "scene/camera_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/budgets.h"

namespace bz::scene {

namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string vec(const glm::dvec3& v) {
    return num(v.x) + "," + num(v.y) + "," + num(v.z);
}

bool in_range(const glm::dvec3& v) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(v[i]) || std::abs(v[i]) > budget::kCameraExtent) return false;
    }
    return true;
}

}  // namespace

std::string view_problem(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
    const std::string extent = num(budget::kCameraExtent);
    if (!in_range(eye))
        return "the eye (" + vec(eye) + ") is not a finite point within +-" + extent;
    if (!in_range(target))
        return "the target (" + vec(target) + ") is not a finite point within +-" + extent;
    if (!in_range(up) || glm::length(up) <= 0.0)
        return "the up vector (" + vec(up) + ") is zero or not finite";
    const glm::dvec3 dir = target - eye;
    const double dist = glm::length(dir);
    // Relative to the size of the coordinates: at 1e9 a difference of 1e-6 is rounding.
    const double scale = std::max({1.0, glm::length(eye), glm::length(target)});
    if (!(dist > 1e-9 * scale)) return "the eye is at the target (" + vec(eye) + ")";
    const double sine = glm::length(glm::cross(dir / dist, glm::normalize(up)));
    if (!(sine > 1e-6)) {
        return "the view (from " + vec(eye) + " to " + vec(target) +
               ") is parallel to the up vector (" + vec(up) +
               "), so the picture has no up (look less steeply, or choose another up vector)";
    }
    return {};
}

std::string path_view_problem(const glm::dvec3& eye_a, const glm::dvec3& target_a,
                              const glm::dvec3& eye_b, const glm::dvec3& target_b,
                              const glm::dvec3& up, double* at) {
    // The view direction d(f) = da + f (db - da) is linear in f. The view is worst where d is
    // shortest (the eye meets the target) or where its part across `up` is shortest (it looks
    // along `up`); both are minima of a quadratic in f, checked with the ends.
    const glm::dvec3 da = target_a - eye_a, dd = (target_b - eye_b) - da;
    const glm::dvec3 u = glm::length(up) > 0.0 ? glm::normalize(up) : glm::dvec3(0.0, 1.0, 0.0);
    const auto across = [&u](const glm::dvec3& v) { return v - u * glm::dot(v, u); };
    const auto closest = [](const glm::dvec3& a, const glm::dvec3& d) {
        const double dd2 = glm::dot(d, d);
        return dd2 > 0.0 ? std::clamp(-glm::dot(a, d) / dd2, 0.0, 1.0) : 0.0;
    };
    for (const double f : {0.0, 1.0, closest(da, dd), closest(across(da), across(dd))}) {
        const glm::dvec3 eye = eye_a + (eye_b - eye_a) * f;
        const glm::dvec3 target = target_a + (target_b - target_a) * f;
        if (std::string why = view_problem(eye, target, up); !why.empty()) {
            if (at) *at = f;
            return why;
        }
    }
    return {};
}

std::string camera_problem(const Camera& c) {
    if (std::string why = view_problem(c.eye, c.target, c.up); !why.empty()) return why;
    if (!(c.fov_y_deg > 0.0 && c.fov_y_deg < 180.0))
        return "the field of view (" + num(c.fov_y_deg) + " degrees) is not in (0, 180)";
    if (!(std::isfinite(c.near) && std::isfinite(c.far) && c.near > 0.0 &&
          c.far <= budget::kCameraExtent)) {
        return "the near and far planes (" + num(c.near) + ", " + num(c.far) +
               ") are not finite, positive and within " + num(budget::kCameraExtent) +
               " (is the scene's size beyond that?)";
    }
    if (!(c.far > c.near)) {
        return "the near plane (" + num(c.near) + ") is not before the far plane (" + num(c.far) +
               ")";
    }
    return {};
}

}  // namespace bz::scene
