#include "geometry/vector/path_order.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bz::geo {

double pen_up_travel(std::span<const Polyline> paths) {
    double travel = 0.0;
    for (std::size_t i = 1; i < paths.size(); ++i) {
        if (paths[i - 1].points.empty() || paths[i].points.empty()) continue;
        travel += glm::length(paths[i].points.front() - paths[i - 1].points.back());
    }
    return travel;
}

namespace {

// Both ends of every path in a uniform grid of about one end per cell; used ends are removed,
// so a search scans rings of cells outwards until no nearer end can remain.
class EndGrid {
  public:
    EndGrid(const std::vector<Polyline>& paths, bool both_ends) {
        lo_ = glm::dvec2(std::numeric_limits<double>::max());
        glm::dvec2 hi(std::numeric_limits<double>::lowest());
        for (const Polyline& p : paths) {
            for (const glm::dvec2& e : {p.points.front(), p.points.back()}) {
                lo_ = glm::min(lo_, e);
                hi = glm::max(hi, e);
            }
        }
        const glm::dvec2 extent = glm::max(hi - lo_, glm::dvec2(1e-9));
        const double n = std::max<double>(1.0, static_cast<double>(paths.size()));
        cell_ = std::max(std::sqrt(extent.x * extent.y / n), std::max(extent.x, extent.y) / 4096.0);
        nx_ = static_cast<int>(std::min(4096.0, std::floor(extent.x / cell_) + 1.0));
        ny_ = static_cast<int>(std::min(4096.0, std::floor(extent.y / cell_) + 1.0));
        cells_.resize(static_cast<std::size_t>(nx_) * ny_);
        for (std::size_t i = 0; i < paths.size(); ++i) {
            add(paths[i].points.front(), static_cast<std::uint32_t>(2 * i));
            if (both_ends) add(paths[i].points.back(), static_cast<std::uint32_t>(2 * i + 1));
        }
        ends_.resize(2 * paths.size());
        for (std::size_t i = 0; i < paths.size(); ++i) {
            ends_[2 * i] = paths[i].points.front();
            ends_[2 * i + 1] = paths[i].points.back();
        }
    }

    // The nearest remaining end to `p` (path * 2 + 0 for its first point, + 1 for its last).
    std::uint32_t nearest(glm::dvec2 p) const {
        const int cx = clamp_x(p.x), cy = clamp_y(p.y);
        double best = std::numeric_limits<double>::max();
        std::uint32_t best_end = 0;
        const int max_ring = std::max(nx_, ny_);
        for (int r = 0; r <= max_ring; ++r) {
            for (int y = cy - r; y <= cy + r; ++y) {
                if (y < 0 || y >= ny_) continue;
                const bool edge_row = y == cy - r || y == cy + r;
                const int step = edge_row ? 1 : 2 * r;
                for (int x = cx - r; x <= cx + r; x += std::max(step, 1)) {
                    if (x < 0 || x >= nx_) continue;
                    for (const std::uint32_t e : cells_[index(x, y)]) {
                        const double d = glm::length(ends_[e] - p);
                        if (d < best || (d == best && e < best_end)) {
                            best = d;
                            best_end = e;
                        }
                    }
                }
            }
            // Every end in ring r + 1 or beyond lies at least r cells (clamping aside) away.
            if (best <= r * cell_ && inside(p)) break;
        }
        return best_end;
    }

    void remove_path(std::uint32_t path) {
        for (const std::uint32_t e : {2 * path, 2 * path + 1}) {
            std::vector<std::uint32_t>& c = cells_[index(clamp_x(ends_[e].x), clamp_y(ends_[e].y))];
            const auto it = std::find(c.begin(), c.end(), e);
            if (it != c.end()) {
                *it = c.back();
                c.pop_back();
            }
        }
    }

  private:
    void add(glm::dvec2 p, std::uint32_t e) {
        cells_[index(clamp_x(p.x), clamp_y(p.y))].push_back(e);
    }
    int clamp_x(double x) const {
        return std::clamp(static_cast<int>(std::floor((x - lo_.x) / cell_)), 0, nx_ - 1);
    }
    int clamp_y(double y) const {
        return std::clamp(static_cast<int>(std::floor((y - lo_.y) / cell_)), 0, ny_ - 1);
    }
    bool inside(glm::dvec2 p) const {
        return p.x >= lo_.x && p.y >= lo_.y && p.x < lo_.x + nx_ * cell_ &&
               p.y < lo_.y + ny_ * cell_;
    }
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) +
               static_cast<std::size_t>(x);
    }

    glm::dvec2 lo_{0.0};
    double cell_ = 1.0;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<std::uint32_t>> cells_;
    std::vector<glm::dvec2> ends_;
};

}  // namespace

glm::dvec2 order_nearest_end(std::vector<Polyline>& paths, glm::dvec2 start, bool may_reverse) {
    if (paths.empty()) return start;
    EndGrid grid(paths, may_reverse);
    std::vector<Polyline> ordered;
    ordered.reserve(paths.size());
    glm::dvec2 pen = start;
    for (std::size_t k = 0; k < paths.size(); ++k) {
        const std::uint32_t end = grid.nearest(pen);
        const std::uint32_t path = end / 2;
        grid.remove_path(path);
        Polyline p = std::move(paths[path]);
        if (end % 2 == 1) std::reverse(p.points.begin(), p.points.end());
        pen = p.points.back();
        ordered.push_back(std::move(p));
    }
    paths = std::move(ordered);
    return pen;
}

}  // namespace bz::geo
