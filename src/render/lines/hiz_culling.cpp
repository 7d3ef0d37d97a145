#include "render/lines/hiz_culling.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

namespace {

// Pixels added around a sphere's rectangle: the spine test reads the texel under a sample and
// its four neighbours (stored_inv_depth_at), and samples sit up to 0.75 px off the spine.
constexpr float kRectMargin = 2.0f;

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

HizView::HizView(const glm::mat4& proj, float near_plane, int w, int h)
    : fx(proj[0][0]),
      sx(proj[2][0]),
      fy(proj[1][1]),
      sy(proj[2][1]),
      near(near_plane),
      width(w),
      height(h) {
    // Clip x, y and w of a perspective projection take nothing else of the point.
    usable = proj[0][1] == 0.0f && proj[1][0] == 0.0f && proj[3][0] == 0.0f && proj[3][1] == 0.0f &&
             proj[0][3] == 0.0f && proj[1][3] == 0.0f && proj[2][3] == -1.0f &&
             proj[3][3] == 0.0f && fx > 0.0f && fy > 0.0f && w > 0 && h > 0 && near_plane > 0.0f;
}

std::optional<ScreenRect> sphere_screen_rect(const HizView& view, const glm::vec3& center,
                                             float radius) {
    // Every point of the box around the sphere lies at a view depth d in [dn, df] (beyond
    // the near plane) and at x in [cx - r, cx + r]: its window x, (fx x / d - sx), is
    // extreme at a corner, so two divisions per side bound it.
    const float dn = -(center.z + radius), df = -(center.z - radius);
    if (!view.usable || !(dn > view.near) || !std::isfinite(df)) return std::nullopt;
    const auto span = [&](float c, float f, float s, int size) {
        const float lo = std::min((c - radius) / dn, (c - radius) / df);
        const float hi = std::max((c + radius) / dn, (c + radius) / df);
        const float half = 0.5f * static_cast<float>(size);
        return glm::vec2((f * lo - s) * half + half, (f * hi - s) * half + half);
    };
    const glm::vec2 x = span(center.x, view.fx, view.sx, view.width);
    const glm::vec2 y = span(center.y, view.fy, view.sy, view.height);
    return ScreenRect{glm::vec2(x.x, y.x), glm::vec2(x.y, y.y)};
}

HizBounds hiz_bounds(const HizView& view, const glm::vec3& center, float radius) {
    const std::optional<ScreenRect> rect = sphere_screen_rect(view, center, radius);
    if (!rect) return kNoHizTest;
    const float dn = -(center.z + radius);  // the sphere's nearest view depth
    const glm::vec2 lo = rect->lo - kRectMargin;
    const glm::vec2 hi = rect->hi + kRectMargin;
    const auto w = static_cast<float>(view.width), h = static_cast<float>(view.height);
    // Wholly off screen: the frustum test's business (its guard band keeps such clusters).
    if (!(hi.x >= 0.0f && hi.y >= 0.0f && lo.x < w && lo.y < h)) return kNoHizTest;
    // Clamped to the screen: the spine test clamps its texel reads the same way.
    const glm::ivec2 a(std::max(lo.x, 0.0f), std::max(lo.y, 0.0f));
    const glm::ivec2 b(std::min(hi.x, w - 1.0f), std::min(hi.y, h - 1.0f));
    for (int level = 0; level < 2; ++level) {
        const int tile = kDepthTileSize * (level == 0 ? 1 : kCoarseDepthTiles);
        const glm::ivec2 t0 = a / tile, t1 = b / tile;
        const glm::ivec2 n = t1 - t0 + 1;
        if (n.x * n.y > kMaxHizTiles) continue;
        return HizBounds(pack(t0.x, t0.y), pack(t1.x, t1.y), glm::floatBitsToUint(1.0f / dn),
                         static_cast<std::uint32_t>(level + 1));
    }
    return kNoHizTest;
}

}  // namespace bz::render
