#pragma once
// Hierarchical-Z culling of edge clusters against the prepass (LineMethod::compute): after the
// prepass, the depth tiles pass (pass_depth_tiles.cpp, shaders/lines/depth_tiles.comp) keeps
// for each square of kDepthTileSize pixels, and for each square of kDepthTileSize *
// kCoarseDepthTiles, the inverse view depth of the farthest surface in it. Each cluster the
// CPU kept gets a bounds record here: the screen rectangle its bounding sphere covers and the
// sphere's nearest inverse depth. edges.comp skips the cluster's work group when every tile
// under the rectangle holds a surface nearer than the sphere by more than the spine test's
// tolerance: then every spine sample of every edge in it fails the spine test anyway.
//
// Conservative by construction: a sphere reaching behind the eye's near plane, or whose
// rectangle covers more than kMaxHizTiles of the coarse tiles, gets no test. The test is off
// where hidden lines are drawn (no occlusion) and where the frame is too small for it to pay
// (hiz_culls, render/passes.h).
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

namespace bz::render {

inline constexpr int kDepthTileSize = 16;    // pixels per fine depth tile, each way
inline constexpr int kCoarseDepthTiles = 8;  // fine tiles per coarse tile, each way
inline constexpr int kMaxHizTiles = 64;      // most tiles one cluster's test reads

// The depth tiles of a `width` x `height` frame: fine and coarse counts.
struct DepthTileGrid {
    glm::ivec2 fine{0};
    glm::ivec2 coarse{0};
};
DepthTileGrid depth_tile_grid(int width, int height);

// What bounds records need of the view: a perspective projection whose clip x and y are
// (fx x + sx z, fy y + sy z) over w = -z (glm::perspective, glm::frustum; reversed-Z or not),
// the near plane and the screen size. Any other projection gets no test.
struct HizView {
    HizView(const glm::mat4& proj, float near, int width, int height);
    bool usable = false;
    float fx = 1.0f, sx = 0.0f, fy = 1.0f, sy = 0.0f;
    float near = 0.1f;
    int width = 0, height = 0;  // pixels
};

// The window rectangle (pixels, unclamped, no margin) that a view-space sphere covers, when the
// sphere lies wholly beyond the near plane; nullopt otherwise. Also what the compute prepass
// routes clusters by (prepass_raster.h).
struct ScreenRect {
    glm::vec2 lo{0.0f}, hi{0.0f};
};
std::optional<ScreenRect> sphere_screen_rect(const HizView& view, const glm::vec3& center,
                                             float radius);

// A cluster's record for edges.comp (one uvec4): x = x0 | y0 << 16 and y = x1 | y1 << 16, the
// tile rectangle (inclusive) on level w - 1 (0 fine, 1 coarse); z the float bits of the
// sphere's nearest inverse view depth; w = 0: no test.
using HizBounds = glm::uvec4;
inline constexpr HizBounds kNoHizTest{0u};

// The record of a view-space sphere. In float: one per cluster per frame, on the CPU, so it
// must cost next to nothing; its margins (two pixels, and the shader's depth slack) are far
// above float rounding.
HizBounds hiz_bounds(const HizView& view, const glm::vec3& center, float radius);

}  // namespace bz::render
