#include "cli/camera_options.h"

#include <string>

#include "scene/camera_check.h"

namespace bz::app {

bool parse_camera_option(std::string_view a, ArgCursor& cur, CameraArgs& o) {
    if (a == "--size") {
        o.size = parse_size(a, cur.value(a));
        return true;
    }
    if (a == "--eye") {
        o.eye = parse_vec3(a, cur.value(a));
    } else if (a == "--target") {
        o.target = parse_vec3(a, cur.value(a));
    } else if (a == "--up") {
        o.up = parse_vec3(a, cur.value(a));
    } else if (a == "--fov") {
        o.fov = parse_number(a, cur.value(a));
    } else if (a == "--near") {
        o.near = parse_number(a, cur.value(a));
    } else if (a == "--far") {
        o.far = parse_number(a, cur.value(a));
    } else {
        return false;
    }
    o.any_view_option = true;
    return true;
}

void validate_camera(const CameraArgs& o) {
    if (!(o.fov > 0.0 && o.fov < 180.0)) throw UsageError("--fov must be in (0, 180)");
    if (o.near && *o.near <= 0.0) throw UsageError("--near must be > 0");
    if (o.near && o.far && *o.far <= *o.near) throw UsageError("--far must be > --near");
    if (o.eye && o.target && glm::length(*o.eye - *o.target) <= 0.0) {
        throw UsageError("--eye and --target must differ");
    }
    if (glm::length(o.up) <= 0.0) throw UsageError("--up must not be zero");
    // With both ends of the view given, the rest of the camera can be judged now.
    if (o.eye && o.target) {
        if (const std::string why = scene::view_problem(*o.eye, *o.target, o.up); !why.empty())
            throw UsageError("the camera cannot make a picture: " + why);
    }
}

}  // namespace bz::app
