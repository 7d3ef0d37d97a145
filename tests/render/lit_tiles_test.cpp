// The list of lit tiles (pass_tiles.cpp, shaders/beam/lit_tiles.glsl, tile_list.comp): built
// from the marks of the passes that know where light is, it must hold exactly the tiles the
// documented rule gives - the tile of every lit pixel of the beam image, every tile a bilinear
// fetch of a non-zero bloom texel can reach, and with the phosphor every tile where last
// frame's picture held light - on a screen whose last tile row and column are cut off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "render/renderer.h"
#include "render/targets.h"
#include "support/gl_test.h"

namespace {

// Divisible by the bloom's 4, not by the 16-pixel tiles: 21 x 16 tiles, the last column 8
// pixels wide and the last row 4 pixels high.
constexpr int kLitW = 328;
constexpr int kLitH = 244;
constexpr int kT = bz::render::kLitTileSize;
constexpr int kTilesX = (kLitW + kT - 1) / kT;
constexpr int kTilesY = (kLitH + kT - 1) / kT;

using Tiles = std::set<std::pair<int, int>>;  // (x, y), GL's order: row 0 at the bottom

// A HUD point at pixel (x, y) of GL's order (row 0 at the bottom).
glm::vec2 at(float x, float y) {
    return {(x + 0.5f - kLitW * 0.5f) / (kLitH * 0.5f), (y + 0.5f - kLitH * 0.5f) / (kLitH * 0.5f)};
}

// Dots in the first and the last (cut-off) tile, a line along the boundary between two tile
// columns, a dot in the middle of a tile far from the rest, and a faint line on the top row.
bz::scene::FrameList analytic_lines(double time_s) {
    bz::scene::FrameList f;
    f.time_s = time_s;
    const glm::vec3 green{0.1f, 1.0f, 0.1f};
    f.hud.push_back({at(1, 1), at(1, 1), green, 1.0f});
    f.hud.push_back({at(kLitW - 2, kLitH - 2), at(kLitW - 2, kLitH - 2), green, 1.0f});
    f.hud.push_back({at(5 * kT, 3 * kT + 4), at(5 * kT, 9 * kT + 4), green, 1.0f});
    f.hud.push_back({at(14 * kT + 8, 7 * kT + 8), at(14 * kT + 8, 7 * kT + 8), green, 1.2f});
    f.hud.push_back({at(40, kLitH - 1), at(120, kLitH - 1), green, 0.05f});
    return f;
}

Tiles listed(bz::render::Renderer& r) {
    Tiles out;
    for (const glm::ivec2 t : r.read_lit_tiles()) {
        EXPECT_TRUE(t.x >= 0 && t.y >= 0 && t.x < kTilesX && t.y < kTilesY) << t.x << "," << t.y;
        out.insert({t.x, t.y});
    }
    return out;
}

// The tiles holding a pixel whose brightest channel is above zero; `hdr` has row 0 at the top.
Tiles tiles_of_lit_pixels(const std::vector<float>& hdr) {
    Tiles out;
    for (int y = 0; y < kLitH; ++y) {
        for (int x = 0; x < kLitW; ++x) {
            const std::size_t i = (static_cast<std::size_t>(kLitH - 1 - y) * kLitW + x) * 4;
            if (std::max({hdr[i], hdr[i + 1], hdr[i + 2]}) > 0.0f) out.insert({x / kT, y / kT});
        }
    }
    return out;
}

// Every tile holding a pixel that a bilinear fetch reading a non-zero texel i of the finished
// bloom can be centred on, one pixel of margin included, `f` screen pixels per texel
// (lit_tiles.glsl's mark_bloom_texel): x in [ceil((i - 0.5) f - 0.5) - 1, ceil((i + 1.5) f -
// 0.5)], that is [4i - 3, 4i + 6] at a quarter-resolution bloom.
Tiles tiles_reached_by_bloom(bz::render::Renderer& r) {
    glm::ivec2 size;
    const std::vector<std::uint8_t> bloom = r.read_bloom(&size);
    const int f = kLitW / size.x;
    EXPECT_EQ(f * size.x, kLitW);
    EXPECT_EQ(f * size.y, kLitH);
    Tiles out;
    for (int j = 0; j < size.y; ++j) {
        for (int i = 0; i < size.x; ++i) {
            const std::size_t k = (static_cast<std::size_t>(j) * size.x + i) * 4;
            if (std::max({bloom[k], bloom[k + 1], bloom[k + 2]}) == 0) continue;
            const auto lo = [f](int t) {
                return static_cast<int>(std::ceil((t - 0.5) * f - 0.5)) - 1;
            };
            const auto hi = [f](int t) { return static_cast<int>(std::ceil((t + 1.5) * f - 0.5)); };
            const int x0 = std::clamp(lo(i), 0, kLitW - 1) / kT;
            const int x1 = std::clamp(hi(i), 0, kLitW - 1) / kT;
            const int y0 = std::clamp(lo(j), 0, kLitH - 1) / kT;
            const int y1 = std::clamp(hi(j), 0, kLitH - 1) / kT;
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) out.insert({x, y});
        }
    }
    return out;
}

Tiles united(Tiles a, const Tiles& b) {
    a.insert(b.begin(), b.end());
    return a;
}

// The tiles the analytic frame's lines light: each dot and line is drawn well inside its
// tiles (half-width 2 px, caps included), except the column line, which straddles x = 5T.
Tiles analytic_tiles() {
    Tiles t = {{0, 0}, {kTilesX - 1, kTilesY - 1}, {14, 7}};
    for (int y = 3; y <= 9; ++y) {
        t.insert({4, y});
        t.insert({5, y});
    }
    for (int x = 40 / kT; x <= 122 / kT; ++x) t.insert({x, kTilesY - 1});
    return t;
}

class LitTilesTest : public bz::test::GlTest {};

}  // namespace

TEST_F(LitTilesTest, WithoutGlowTheListIsTheTilesOfTheLitPixelsScreenEdgesIncluded) {
    auto s = bz::render::preset("balanced");  // classic beam, quarter-resolution bloom
    s.beam.bloom_threshold = 1e6f;            // bloom runs, but nothing glows
    s.beam.bloom_knee = 0.0f;
    bz::scene::MeshLibrary meshes;
    bz::render::Renderer r(s, kLitW, kLitH, bz::gl::TimingMethod::off);
    r.render(analytic_lines(0.0), meshes, bz::render::Renderer::kOffscreen);
    EXPECT_TRUE(tiles_reached_by_bloom(r).empty()) << "the threshold should leave no glow";
    const Tiles lit = tiles_of_lit_pixels(r.read_lines_hdr());
    EXPECT_EQ(lit, analytic_tiles()) << "the frame is not the analytic one the test assumes";
    EXPECT_EQ(listed(r), lit);
}

TEST_F(LitTilesTest, GlowDilatesTheListByTheBloomsBilinearReachInBothLooks) {
    for (const char* look : {"classic", "mame"}) {
        SCOPED_TRACE(look);
        auto s = bz::render::preset("balanced");
        s.beam = bz::render::beam_look(look);
        s.beam.phosphor = bz::render::PhosphorDecay::off;
        s.hud_glow = true;  // the analytic HUD lines stand for glowing beam lines
        bz::scene::MeshLibrary meshes;
        bz::render::Renderer r(s, kLitW, kLitH, bz::gl::TimingMethod::off);
        r.render(analytic_lines(0.0), meshes, bz::render::Renderer::kOffscreen);
        const Tiles lit = tiles_of_lit_pixels(r.read_lines_hdr());
        const Tiles glow = tiles_reached_by_bloom(r);
        const Tiles expected = united(lit, glow);
        EXPECT_EQ(listed(r), expected);
        // The glow reaches tiles beyond the lit ones (the dilation is tested), but not the
        // whole screen (the list means something).
        EXPECT_GT(expected.size(), lit.size());
        EXPECT_LT(expected.size(), static_cast<std::size_t>(kTilesX * kTilesY) * 3 / 4);
        // The dot alone in the middle of tile (14, 7): its glow stays within one tile of it.
        for (int y = 4; y <= 10; ++y) {
            EXPECT_FALSE(expected.count({11, y}) || expected.count({17, y}))
                << "the dot's glow reached 3 tiles away, row " << y;
        }
    }
}

// With the phosphor a tile must be shaded where the picture still glows from earlier frames
// though nothing is drawn there now: a frame with nothing in it lists the tiles last frame's
// picture lit, and they fade to black tile by tile until the list is empty.
TEST_F(LitTilesTest, WithThePhosphorTheListHoldsTheTilesWhereLastFramesPictureGlows) {
    auto s = bz::render::preset("balanced");
    s.beam = bz::render::beam_look("mame");
    s.beam.persistence_ms = 30.0f;
    bz::scene::MeshLibrary meshes;
    bz::render::Renderer r(s, kLitW, kLitH, bz::gl::TimingMethod::off);
    r.render(analytic_lines(0.0), meshes, bz::render::Renderer::kOffscreen);
    Tiles picture = tiles_of_lit_pixels(r.read_picture_hdr());
    ASSERT_FALSE(picture.empty());
    bz::scene::FrameList empty;
    bool emptied = false;
    for (int i = 1; i <= 60 && !emptied; ++i) {
        empty.time_s = i * 0.05;
        r.render(empty, meshes, bz::render::Renderer::kOffscreen);
        const Tiles list = listed(r);
        EXPECT_EQ(list, united(picture, tiles_reached_by_bloom(r))) << "frame " << i;
        picture = tiles_of_lit_pixels(r.read_picture_hdr());
        emptied = list.empty();
    }
    EXPECT_TRUE(emptied) << "the trail never faded out of the list";
    EXPECT_TRUE(picture.empty());
}

TEST_F(LitTilesTest, TheEveryPixelCompositeListsNoTiles) {
    auto s = bz::render::preset("balanced");
    s.sparse_composite = false;
    bz::scene::MeshLibrary meshes;
    bz::render::Renderer r(s, kLitW, kLitH, bz::gl::TimingMethod::off);
    r.render(analytic_lines(0.0), meshes, bz::render::Renderer::kOffscreen);
    EXPECT_TRUE(r.read_lit_tiles().empty());
}

// The list holds runs of lit tiles along each row (lit_tiles.glsl's encode_tile_run), at most
// kMaxTileRun (256) tiles each: a line across a screen 258 tiles wide is listed as a 256-tile
// run and a 2-tile one, and unpacks to exactly the tiles it lights; a gap splits a run.
TEST_F(LitTilesTest, RunsLongerThanTheirLimitSplitAndGapsEndThem) {
    constexpr int w = 258 * kT, h = 2 * kT;  // divisible by the bloom's 4
    const auto px = [](float x, float y) {
        return glm::vec2((x + 0.5f - w * 0.5f) / (h * 0.5f), (y + 0.5f - h * 0.5f) / (h * 0.5f));
    };
    bz::scene::FrameList f;
    const glm::vec3 green{0.1f, 1.0f, 0.1f};
    f.hud.push_back({px(4, 8), px(w - 5, 8), green, 1.0f});                 // row 0, every tile
    f.hud.push_back({px(4, kT + 8), px(3 * kT - 5, kT + 8), green, 1.0f});  // row 1, tiles 0-2
    f.hud.push_back({px(10 * kT + 4, kT + 8), px(11 * kT - 5, kT + 8), green, 1.0f});  // tile 10
    auto s = bz::render::preset("balanced");
    s.beam.bloom_threshold = 1e6f;  // bloom runs, but nothing glows
    s.beam.bloom_knee = 0.0f;
    bz::scene::MeshLibrary meshes;
    bz::render::Renderer r(s, w, h, bz::gl::TimingMethod::off);
    r.render(f, meshes, bz::render::Renderer::kOffscreen);
    Tiles expected;
    for (int x = 0; x < 258; ++x) expected.insert({x, 0});
    for (int x = 0; x < 3; ++x) expected.insert({x, 1});
    expected.insert({10, 1});
    Tiles got;
    for (const glm::ivec2 t : r.read_lit_tiles()) {
        EXPECT_TRUE(got.insert({t.x, t.y}).second) << "tile listed twice: " << t.x << "," << t.y;
    }
    EXPECT_EQ(got, expected);
}
