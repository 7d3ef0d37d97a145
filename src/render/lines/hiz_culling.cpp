#include "render/lines/hiz_culling.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

namespace {

// Pixels added around a sphere's rectangle: the spine test reads the texel under a sample and
// its four neighbours (stored_inv_depth_at), and samples sit up to 0.75 px off the spine.
constexpr double kRectMargin = 2.0;

std::uint32_t pack(int x, int y) {
    return static_cast<std::uint32_t>(x) | (static_cast<std::uint32_t>(y) << 16);
}

}  // namespace

DepthTileGrid depth_tile_grid(int width, int height) {
    const glm::ivec2 fine((width + kDepthTileSize - 1) / kDepthTileSize,
                          (height + kDepthTileSize - 1) / kDepthTileSize);
    const glm::ivec2 coarse((fine.x + kCoarseDepthTiles - 1) / kCoarseDepthTiles,
                            (fine.y + kCoarseDepthTiles - 1) / kCoarseDepthTiles);
    return {fine, coarse};
}

HizBounds hiz_bounds(const HizView& view, const glm::dvec3& center, double radius) {
    // The nearest point of the sphere must lie beyond the near plane: then so does the whole
    // box around it, and each corner projects to a finite point.
    const double nearest = -(center.z + radius);
    if (!(nearest > static_cast<double>(view.near)) || !std::isfinite(nearest) || view.width <= 0 ||
        view.height <= 0)
        return kNoHizTest;
    const glm::dmat4 proj(view.proj);
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    // The projection of the box around the sphere is the hull of its corners' projections.
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p =
            center + radius * glm::dvec3((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                                         (corner & 4) ? 1.0 : -1.0);
        const glm::dvec4 clip = proj * glm::dvec4(p, 1.0);
        if (!(clip.w > 0.0)) return kNoHizTest;
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        const glm::dvec2 px = (ndc * 0.5 + 0.5) * glm::dvec2(view.width, view.height);
        lo = glm::min(lo, px);
        hi = glm::max(hi, px);
    }
    lo -= kRectMargin;
    hi += kRectMargin;
    // Wholly off screen: the frustum test's business (its guard band keeps such clusters).
    if (!(hi.x >= 0.0 && hi.y >= 0.0 && lo.x < view.width && lo.y < view.height)) return kNoHizTest;
    // Clamped to the screen: the spine test clamps its texel reads the same way.
    const glm::ivec2 max_px(view.width - 1, view.height - 1);
    const glm::ivec2 a =
        glm::clamp(glm::ivec2(glm::floor(glm::max(lo, glm::dvec2(0.0)))), glm::ivec2(0), max_px);
    const glm::ivec2 b =
        glm::clamp(glm::ivec2(glm::floor(glm::min(hi, glm::dvec2(max_px)))), glm::ivec2(0), max_px);
    for (int level = 0; level < 2; ++level) {
        const int tile = kDepthTileSize * (level == 0 ? 1 : kCoarseDepthTiles);
        const glm::ivec2 t0 = a / tile, t1 = b / tile;
        const glm::ivec2 n = t1 - t0 + 1;
        if (n.x * n.y > kMaxHizTiles) continue;
        const auto inv = static_cast<float>(1.0 / nearest);
        return HizBounds(pack(t0.x, t0.y), pack(t1.x, t1.y), glm::floatBitsToUint(inv),
                         static_cast<std::uint32_t>(level + 1));
    }
    return kNoHizTest;
}

}  // namespace bz::render
