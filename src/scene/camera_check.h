#pragma once
// The one test every command puts a camera through before it draws: a camera that cannot make
// a picture (its up vector along the view, the eye at the target, near >= far, a coordinate
// that is not finite or beyond budget::kCameraExtent) gets one clear message instead of an empty
// picture with exit 0 or an internal error deep in the renderer or the reference.
#include <glm/glm.hpp>
#include <string>

#include "scene/frame_list.h"

namespace bz::scene {

// Why eye, target and up give no view direction, or "" when they do.
std::string view_problem(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);

// Why some camera on the straight path between two keys cannot make a picture, or "" when
// every one can. Eye and target each move linearly from the first key to the second (as a
// level's camera path is played), so a view that passes straight up or down, or an eye that
// passes through the target, between two good keys is found. `at` gets the fraction of the
// way (0..1) where the worst view is.
std::string path_view_problem(const glm::dvec3& eye_a, const glm::dvec3& target_a,
                              const glm::dvec3& eye_b, const glm::dvec3& target_b,
                              const glm::dvec3& up, double* at = nullptr);

// Why `camera` cannot make a picture, or "" when it can: view_problem, then the field of view
// and the near and far planes.
std::string camera_problem(const Camera& camera);

}  // namespace bz::scene
