#include <algorithm>

#include "geometry/mesh.h"

namespace bz::geo {

Bounds compute_bounds(const std::vector<glm::vec3>& positions) {
    Bounds b;
    if (positions.empty()) return b;
    b.min = b.max = positions.front();
    for (const auto& p : positions) {
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    }
    return b;
}

}  // namespace bz::geo
