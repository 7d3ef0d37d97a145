#include "app/commands/camera_args.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/budgets.h"
#include "core/error.h"
#include "render/camera/camera_framing.h"
#include "scene/camera_check.h"

namespace bz::app {

scene::Camera camera_for(const CameraArgs& o, const geo::Bounds& bounds) {
    for (const glm::vec3& corner : {bounds.min, bounds.max}) {
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(corner[i]) || std::abs(corner[i]) > budget::kCameraExtent) {
                char buf[160];
                std::snprintf(buf, sizeof buf,
                              "the model reaches a coordinate of %.6g, beyond the +-%.6g a "
                              "picture is made at: no camera can frame it",
                              static_cast<double>(corner[i]), budget::kCameraExtent);
                throw UserError(buf);
            }
        }
    }
    const double aspect = static_cast<double>(o.size.x) / o.size.y;
    scene::Camera c = render::frame_bounds(bounds, o.fov, aspect);
    if (o.eye) {
        c.eye = *o.eye;
        c.target = o.target.value_or(glm::dvec3(bounds.center()));
        const double dist = glm::length(c.eye - c.target);
        const double r = std::max(static_cast<double>(bounds.radius()), 1e-6);
        c.near = std::max(dist - r * 1.5, dist * 1e-3);
        c.far = dist + r * 1.5;
    } else if (o.target) {
        c.target = *o.target;
    }
    c.up = o.up;
    c.fov_y_deg = o.fov;
    if (o.near) c.near = *o.near;
    if (o.far) c.far = *o.far;
    // Framing alone keeps near < far; a given --near or --far that crosses the framed other
    // plane is the user's to fix, so it is reported, never silently moved.
    if (!o.near && !o.far && c.far <= c.near) c.far = c.near * 2.0;
    if (const std::string why = scene::camera_problem(c); !why.empty())
        throw UserError("the camera cannot make a picture: " + why);
    return c;
}

}  // namespace bz::app
