#pragma once
// The camera options shared by `render` and `reference` (--eye --target --up --fov --near
// --far --size), parsed and checked without a model or GL; app/commands/camera_args.h turns
// them into a camera once the model's bounds are known.
#include <glm/glm.hpp>
#include <optional>
#include <string_view>

#include "cli/cli_args.h"

namespace bz::app {

struct CameraArgs {
    std::optional<glm::dvec3> eye, target;
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov = 50.0;
    std::optional<double> near, far;
    glm::ivec2 size{800, 600};
    bool any_view_option = false;  // one of --eye --target --up --fov --near --far was given
};

// If `option` is a camera option, reads its value from `cur` and returns true.
bool parse_camera_option(std::string_view option, ArgCursor& cur, CameraArgs& args);
// Throws UsageError for inconsistent values (fov range, near/far order, eye == target).
void validate_camera(const CameraArgs& args);

}  // namespace bz::app
