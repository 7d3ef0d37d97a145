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
