#include "game/world/field.h"

#include <cmath>

namespace bz::game {

double Field::wrap_coord(double v) const {
    return v - size_ * std::floor((v + half_) / size_);
}

glm::dvec2 Field::delta(glm::dvec2 from, glm::dvec2 to) const {
    glm::dvec2 d = to - from;
    if (wrap_) d = {wrap_coord(d.x), wrap_coord(d.y)};
    return d;
}

glm::dvec2 Field::wrap(glm::dvec2 p) const {
    if (!wrap_) return p;
    return {wrap_coord(p.x), wrap_coord(p.y)};
}

bool Field::contains(glm::dvec2 p, double margin) const {
    if (wrap_) return true;
    const double h = half_ - margin;
    return p.x >= -h && p.x <= h && p.y >= -h && p.y <= h;
}

}  // namespace bz::game
