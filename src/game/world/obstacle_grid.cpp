#include "game/world/obstacle_grid.h"

#include <algorithm>
#include <cmath>

#include "game/world/collision.h"

namespace bz::game {

ObstacleGrid::ObstacleGrid(const std::vector<scene::Entity>& obstacles, const Field& field,
                           double cell)
    : field_(field), cell_(cell) {
    n_ = std::clamp(static_cast<int>(std::ceil(field.size() / cell_)), 1, 512);
    cell_ = field.size() / n_;
    const std::size_t cells = static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_);
    // Two passes (count, then fill) give a compact cell -> obstacles table.
    std::vector<std::uint32_t> count(cells + 1, 0);
    auto for_cells = [&](const scene::Entity& o, auto&& fn) {
        const double reach = bounding_radius(o.collider) * o.transform.scale;
        const Range rx = cells_along(o.transform.position.x, reach);
        const Range rz = cells_along(o.transform.position.z, reach);
        for (int i = 0; i < rx.count; ++i) {
            for (int j = 0; j < rz.count; ++j)
                fn(static_cast<std::size_t>(index(rz.lo + j)) * n_ + index(rx.lo + i));
        }
    };
    for (const scene::Entity& o : obstacles) for_cells(o, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    start_ = count;
    items_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t k = 0; k < obstacles.size(); ++k) {
        for_cells(obstacles[k], [&](std::size_t c) { items_[fill[c]++] = k; });
    }
}

ObstacleGrid::Range ObstacleGrid::cells_along(double centre, double reach) const {
    const double half = field_.size() * 0.5;
    int lo = static_cast<int>(std::floor((centre - reach + half) / cell_));
    int hi = static_cast<int>(std::floor((centre + reach + half) / cell_));
    if (!field_.wraps()) {
        // Off-field positions fall into the border cells; clamping keeps overlaps overlapping.
        lo = std::clamp(lo, 0, n_ - 1);
        hi = std::clamp(hi, 0, n_ - 1);
    }
    return {lo, std::min(hi - lo + 1, n_)};
}

int ObstacleGrid::index(int k) const {
    return ((k % n_) + n_) % n_;
}

void ObstacleGrid::near(glm::dvec2 p, double radius, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (n_ == 0) return;
    const Range rx = cells_along(p.x, radius);
    const Range rz = cells_along(p.y, radius);
    for (int j = 0; j < rz.count; ++j) {
        const std::size_t row = static_cast<std::size_t>(index(rz.lo + j)) * n_;
        for (int i = 0; i < rx.count; ++i) {
            const std::size_t c = row + index(rx.lo + i);
            out.insert(out.end(), items_.begin() + start_[c], items_.begin() + start_[c + 1]);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace bz::game
