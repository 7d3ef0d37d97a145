#pragma once
// The square battlefield on the ground plane (x, z), centred on the origin. With wrap on,
// leaving one edge enters the opposite one, so distances are measured the short way round.
#include <glm/glm.hpp>

namespace bz::game {

class Field {
  public:
    Field() = default;
    Field(double size, bool wrap) : size_(size), half_(size * 0.5), wrap_(wrap) {}

    double size() const { return size_; }
    bool wraps() const { return wrap_; }

    // The vector from a to b on the ground (x, z), the short way round when wrapping.
    glm::dvec2 delta(glm::dvec2 from, glm::dvec2 to) const;
    // Brings a position back into the field when wrapping; unchanged otherwise.
    glm::dvec2 wrap(glm::dvec2 p) const;
    // True when p lies on the field (always true when wrapping).
    bool contains(glm::dvec2 p, double margin = 0.0) const;
    double distance(glm::dvec2 a, glm::dvec2 b) const { return glm::length(delta(a, b)); }

  private:
    double wrap_coord(double v) const;
    double size_ = 400.0;
    double half_ = 200.0;
    bool wrap_ = true;
};

inline glm::dvec2 ground(const glm::dvec3& p) {
    return {p.x, p.z};
}

}  // namespace bz::game
