#pragma once
#include "geometry/mesh.h"
#include "scene/frame_list.h"

namespace bz::render {

// A 3/4 view (from the front-right, above) that fits the whole bounding box in the frame.
scene::Camera frame_bounds(const geo::Bounds& bounds, double fov_y_deg, double aspect);

}  // namespace bz::render
