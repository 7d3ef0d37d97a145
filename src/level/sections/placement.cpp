#include "level/sections/placement.h"

#include <algorithm>
#include <cmath>

namespace bz::level {

glm::dvec2 ground_delta(glm::dvec3 a, glm::dvec3 b, double field_size, bool wrap) {
    glm::dvec2 d{b.x - a.x, b.z - a.z};
    if (wrap && field_size > 0.0) {
        d.x -= field_size * std::round(d.x / field_size);
        d.y -= field_size * std::round(d.y / field_size);
    }
    return d;
}

double footprint_distance(const ObjectDesc& object, const BuiltinKind& kind, glm::dvec3 point,
                          double field_size, bool wrap) {
    const glm::dvec2 d = ground_delta(object.position, point, field_size, wrap);
    if (kind.shape == KindShape::model) {
        return std::max(0.0, glm::length(d) - object.footprint_radius);
    }
    // Into the object's frame: the inverse of a rotation by heading about +y (see kinds.h).
    const double a = glm::radians(object.heading_deg);
    const double c = std::cos(a);
    const double s = std::sin(a);
    const glm::dvec2 local{c * d.x - s * d.y, s * d.x + c * d.y};
    const glm::dvec2 half{kind.half_x * object.scale, kind.half_z * object.scale};
    const glm::dvec2 outside = glm::max(glm::abs(local) - half, glm::dvec2(0.0));
    return glm::length(outside);
}

}  // namespace bz::level
