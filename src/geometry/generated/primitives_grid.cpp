#include <algorithm>
#include <stdexcept>

#include "geometry/generated/primitives.h"

namespace bz::geo {
namespace {

struct GridFrame {
    float size;
    glm::vec2 origin;  // position of cell corner (0, 0)

    // Computed from the global corner index only, so tiles sharing a border produce
    // bit-identical duplicates.
    glm::vec3 corner(std::uint32_t gx, std::uint32_t gz) const {
        return {origin.x + static_cast<float>(gx) * size, 0.0f,
                origin.y + static_cast<float>(gz) * size};
    }
};

// One tile: cells [x0, x1) x [z0, z1) on vertices of its own.
void add_tile(TriMesh& m, const GridFrame& f, std::uint32_t x0, std::uint32_t x1, std::uint32_t z0,
              std::uint32_t z1) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const std::uint32_t row = x1 - x0 + 1;
    for (std::uint32_t z = z0; z <= z1; ++z) {
        for (std::uint32_t x = x0; x <= x1; ++x) m.positions.push_back(f.corner(x, z));
    }
    for (std::uint32_t z = 0; z < z1 - z0; ++z) {
        for (std::uint32_t x = 0; x < x1 - x0; ++x) {
            const std::uint32_t p00 = base + z * row + x, p10 = p00 + 1;
            const std::uint32_t p01 = p00 + row, p11 = p01 + 1;
            // Both triangles face +y.
            m.indices.insert(m.indices.end(), {p00, p01, p10, p10, p01, p11});
        }
    }
}

}  // namespace

TriMesh grid(std::uint32_t nx, std::uint32_t nz, float size, std::uint32_t tile) {
    if (nx == 0 || nz == 0 || tile == 0 || !(size > 0.0f)) {
        throw std::invalid_argument("grid: invalid size or count");
    }
    const GridFrame frame{
        size, {-0.5f * size * static_cast<float>(nx), -0.5f * size * static_cast<float>(nz)}};
    TriMesh m;
    m.indices.reserve(std::size_t{nx} * nz * 6);
    for (std::uint32_t z0 = 0; z0 < nz; z0 += tile) {
        for (std::uint32_t x0 = 0; x0 < nx; x0 += tile) {
            add_tile(m, frame, x0, std::min(nx, x0 + tile), z0, std::min(nz, z0 + tile));
        }
    }
    return m;
}

}  // namespace bz::geo
