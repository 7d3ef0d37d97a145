#pragma once
// Ground-plane geometry of obstacle footprints, for placement checks.
#include <glm/glm.hpp>

#include "level/kinds.h"
#include "level/level.h"

namespace bz::level {

// b - a in the ground plane (x, z); on a wrapping field, the shortest way round.
glm::dvec2 ground_delta(glm::dvec3 a, glm::dvec3 b, double field_size, bool wrap);

// Distance in the ground plane from `point` to the footprint of `object` (0 when inside):
// the scaled, rotated base rectangle of a built-in kind, or a circle of footprint_radius
// for a model.
double footprint_distance(const ObjectDesc& object, const BuiltinKind& kind, glm::dvec3 point,
                          double field_size, bool wrap);

}  // namespace bz::level
