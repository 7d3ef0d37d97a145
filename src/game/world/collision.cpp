#include "game/world/collision.h"

#include <algorithm>
#include <cmath>

namespace bz::game {

namespace {

// Into the collider's own frame: undo the yaw. Transform::forward() is (-sin, -cos) for yaw,
// so a local (x, z) maps to world (x cos + z sin, -x sin + z cos).
glm::dvec2 to_local(glm::dvec2 p, double yaw) {
    const double c = std::cos(yaw);
    const double s = std::sin(yaw);
    return {p.x * c - p.y * s, p.x * s + p.y * c};
}

double box_distance(glm::dvec2 local, glm::dvec2 half) {
    const glm::dvec2 q = glm::abs(local) - half;
    const double outside = glm::length(glm::max(q, glm::dvec2(0.0)));
    const double inside = std::min(std::max(q.x, q.y), 0.0);
    return outside + inside;
}

}  // namespace

bool circle_hits(const scene::Collider& collider, double yaw, double scale, glm::dvec2 offset,
                 double radius) {
    switch (collider.shape) {
        case scene::ColliderShape::none:
            return false;
        case scene::ColliderShape::circle:
            return glm::length(offset) < collider.radius * scale + radius;
        case scene::ColliderShape::box:
            return box_distance(to_local(offset, yaw), collider.half_extent * scale) < radius;
    }
    return false;
}

double bounding_radius(const scene::Collider& collider) {
    switch (collider.shape) {
        case scene::ColliderShape::none:
            return 0.0;
        case scene::ColliderShape::circle:
            return collider.radius;
        case scene::ColliderShape::box:
            return glm::length(collider.half_extent);
    }
    return 0.0;
}

bool segment_hits(const scene::Collider& collider, double yaw, double scale, glm::dvec2 a,
                  glm::dvec2 b, double radius) {
    // Sample the segment finely enough that nothing thinner than the radius slips through.
    const double len = glm::length(b - a);
    const int steps = std::max(1, static_cast<int>(std::ceil(len / std::max(radius, 0.05))));
    for (int i = 0; i <= steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        if (circle_hits(collider, yaw, scale, a + (b - a) * t, radius)) return true;
    }
    return false;
}

}  // namespace bz::game
