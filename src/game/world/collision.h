#pragma once
// Ground-plane overlap tests between a moving circle (a tank, a shell) and a collider.
#include <glm/glm.hpp>

#include "scene/entity.h"

namespace bz::game {

// `offset` is the circle's centre relative to the collider's origin (already the short way
// round on a wrapping field); `yaw` is the collider's rotation.
bool circle_hits(const scene::Collider& collider, double yaw, double scale, glm::dvec2 offset,
                 double radius);

// The radius of a circle around the collider's origin that contains it (before scaling).
double bounding_radius(const scene::Collider& collider);

// Does the segment from a to b (relative to the collider, as above) pass within `radius`?
bool segment_hits(const scene::Collider& collider, double yaw, double scale, glm::dvec2 a,
                  glm::dvec2 b, double radius);

}  // namespace bz::game
