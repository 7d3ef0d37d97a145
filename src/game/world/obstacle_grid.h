#pragma once
// A uniform grid over the field so that "what obstacle is here?" looks at a few nearby
// obstacles instead of all of them (levels hold hundreds). Wraps with the field.
#include <cstdint>
#include <vector>

#include "game/world/field.h"
#include "scene/entity.h"

namespace bz::game {

class ObstacleGrid {
  public:
    ObstacleGrid() = default;
    ObstacleGrid(const std::vector<scene::Entity>& obstacles, const Field& field,
                 double cell = 16.0);

    // Indices of obstacles whose bounding circle may reach within `radius` of p, ascending and
    // without repeats, written to `out` (cleared first).
    void near(glm::dvec2 p, double radius, std::vector<std::uint32_t>& out) const;

  private:
    struct Range {
        int lo = 0;
        int count = 0;
    };
    Range cells_along(double centre, double reach) const;
    int index(int k) const;

    Field field_;
    double cell_ = 16.0;
    int n_ = 0;                         // cells per side
    std::vector<std::uint32_t> start_;  // n*n + 1 offsets into items_
    std::vector<std::uint32_t> items_;  // obstacle indices, cell by cell
};

}  // namespace bz::game
