#include "geometry/reference/mask_score.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace bz::geo {

namespace {

// Box dilation by tol, separably: rows then columns.
std::vector<std::uint8_t> dilate(std::span<const std::uint8_t> m, int w, int h, int tol) {
    std::vector<std::uint8_t> rows(m.size(), 0), out(m.size(), 0);
    auto at = [w](int x, int y) {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
               static_cast<std::size_t>(x);
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!m[at(x, y)]) continue;
            for (int dx = std::max(0, x - tol); dx <= std::min(w - 1, x + tol); ++dx)
                rows[at(dx, y)] = 1;
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (!rows[at(x, y)]) continue;
            for (int dy = std::max(0, y - tol); dy <= std::min(h - 1, y + tol); ++dy)
                out[at(x, dy)] = 1;
        }
    }
    return out;
}

// Fraction of lit pixels of `from` that are lit in `near_to` (already dilated).
double fraction_near(std::span<const std::uint8_t> from, const std::vector<std::uint8_t>& near_to,
                     std::size_t& lit) {
    std::size_t hit = 0;
    lit = 0;
    for (std::size_t i = 0; i < from.size(); ++i) {
        if (!from[i]) continue;
        ++lit;
        hit += near_to[i] ? 1 : 0;
    }
    return lit ? static_cast<double>(hit) / static_cast<double>(lit) : 1.0;
}

}  // namespace

MaskScore score_masks(std::span<const std::uint8_t> test, std::span<const std::uint8_t> ref,
                      int width, int height, int tol) {
    if (width < 1 || height < 1 || tol < 0)
        throw std::invalid_argument("score_masks: bad size or tolerance");
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (test.size() != n || ref.size() != n)
        throw std::invalid_argument("score_masks: mask sizes differ");
    MaskScore s;
    s.precision = fraction_near(test, dilate(ref, width, height, tol), s.test_lit);
    s.recall = fraction_near(ref, dilate(test, width, height, tol), s.ref_lit);
    const double sum = s.precision + s.recall;
    s.f1 = sum > 0.0 ? 2.0 * s.precision * s.recall / sum : 0.0;
    return s;
}

}  // namespace bz::geo
