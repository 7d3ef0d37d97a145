#include <limits>

#include "geometry/line_mesh/clean.h"

namespace bz::geo {

void compact_vertices(std::vector<glm::vec3>& positions, std::vector<std::uint32_t>& triangles) {
    constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(positions.size(), kUnset);
    std::vector<glm::vec3> kept;
    kept.reserve(positions.size());
    for (auto& v : triangles) {
        if (remap[v] == kUnset) {
            remap[v] = static_cast<std::uint32_t>(kept.size());
            kept.push_back(positions[v]);
        }
        v = remap[v];
    }
    positions = std::move(kept);
}

}  // namespace bz::geo
