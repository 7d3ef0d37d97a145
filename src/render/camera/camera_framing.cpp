#include "render/camera/camera_framing.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

scene::Camera frame_bounds(const geo::Bounds& bounds, double fov_y_deg, double aspect) {
    scene::Camera c;
    const glm::dvec3 centre = glm::dvec3(bounds.center());
    const double radius = std::max(static_cast<double>(bounds.radius()), 1e-6);
    const double half_fov = glm::radians(fov_y_deg) * 0.5;
    // Fit the bounding sphere in the narrower of the two fields of view.
    const double half_fit = std::min(half_fov, std::atan(std::tan(half_fov) * aspect));
    const double distance = radius / std::sin(half_fit) * 1.05;
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.8, 0.55, 1.0));
    c.eye = centre + dir * distance;
    c.target = centre;
    c.up = {0.0, 1.0, 0.0};
    c.fov_y_deg = fov_y_deg;
    c.near = std::max(distance - radius * 1.5, distance * 1e-3);
    c.far = distance + radius * 1.5;
    return c;
}

}  // namespace bz::render
