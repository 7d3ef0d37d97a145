#pragma once
// The camera `render` and `reference` make from their camera options (cli/camera_options.h),
// so both put the camera in exactly the same place for the same arguments.
#include <glm/glm.hpp>

#include "cli/camera_options.h"
#include "geometry/mesh.h"
#include "scene/frame_list.h"

namespace bz::app {

// Without --eye: render::frame_bounds' 3/4 view of the bounds. With --eye: near and far fit
// the bounds around the target. Explicit --near/--far win.
scene::Camera camera_for(const CameraArgs& args, const geo::Bounds& bounds);

}  // namespace bz::app
