#pragma once
// The --edit viewer's status line: where the camera is, which way it looks, and which level
// object is under the reticle (with the file:line that places it), plus the key hints.
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "level/level.h"

namespace bz::app {

// The nearest obstacle the view ray from `eye` along `dir` meets before it meets the ground,
// each obstacle taken as an upright cylinder of its footprint radius; nullopt when none.
std::optional<std::size_t> object_under_reticle(const level::Level& level, const glm::dvec3& eye,
                                                const glm::dvec3& dir);

// "X 0.0  Y 6.0  Z 0.0   HEADING 0   PITCH -10   AIM: PYRAMID  classic.toml:14", in capitals
// except the file name. Heading is a compass bearing (0 towards -z, 90 towards +x).
std::string edit_status_line(const level::Level& level, const glm::dvec3& eye, double yaw_deg,
                             double pitch_deg, const glm::dvec3& dir);

}  // namespace bz::app
