// One real game frame through the real renderer: the HUD (radar, reticle, score) and the level
// (horizon, obstacles) must light pixels where the layout puts them, and the ground below the
// horizon must stay mostly dark.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/image_io.h"
#include "game/default_level.h"
#include "game/game.h"
#include "game/hud/hud_layout.h"
#include "render/renderer.h"
#include "support/gl_test.h"
#include "support/tree_paths.h"

namespace {

constexpr int kGameW = 640, kGameH = 360;

struct Frame {
    std::vector<std::uint8_t> rgba;
    int lit(glm::ivec2 lo, glm::ivec2 hi, int channel) const {  // pixels with channel > 60
        int n = 0;
        for (int y = std::max(lo.y, 0); y < std::min(hi.y, kGameH); ++y) {
            for (int x = std::max(lo.x, 0); x < std::min(hi.x, kGameW); ++x) {
                n += rgba[static_cast<std::size_t>((y * kGameW + x) * 4 + channel)] > 60 ? 1 : 0;
            }
        }
        return n;
    }
};

// HUD units (origin at the centre, y up, 1 = half the height) to PNG pixels (row 0 on top).
glm::ivec2 px(glm::vec2 hud) {
    return {static_cast<int>(kGameW * 0.5f + hud.x * kGameH * 0.5f),
            static_cast<int>(kGameH * 0.5f - hud.y * kGameH * 0.5f)};
}

}  // namespace

using GameFrameTest = bz::test::GlTest;

TEST_F(GameFrameTest, LightsHudAndLevelWhereTheyBelong) {
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    bz::game::GameOptions options;
    options.seed = 5;
    options.attract = false;  // straight into play
    bz::game::Game game(bz::game::default_level(), options, &font);
    for (int i = 0; i < 30; ++i) game.tick(bz::game::TickCommand{});
    ASSERT_EQ(game.screen(), bz::game::Screen::playing);

    bz::render::Renderer renderer(bz::render::preset("balanced"), kGameW, kGameH,
                                  bz::gl::TimingMethod::off);
    renderer.render(game.frame(1.0, double(kGameW) / kGameH), game.meshes(),
                    bz::render::Renderer::kOffscreen);
    const Frame f{renderer.read_color()};
    const auto out = bz::test::binary_dir() / "test-out";
    std::filesystem::create_directories(out);
    bz::write_png(out / "game_frame.png", bz::Image{kGameW, kGameH, 4, f.rgba});

    using namespace bz::game::hud;
    // Radar: a red ring around its centre.
    const glm::ivec2 radar_lo = px(kRadarCenter + glm::vec2(-kRadarRadius, kRadarRadius));
    const glm::ivec2 radar_hi = px(kRadarCenter + glm::vec2(kRadarRadius, -kRadarRadius));
    EXPECT_GT(f.lit(radar_lo, radar_hi, 0), 100) << "radar";
    // Score and reserve tanks: red text at the top right.
    EXPECT_GT(f.lit({kGameW * 3 / 4, 0}, {kGameW, kGameH / 5}, 0), 50) << "score";
    // Reticle: green lines around the screen centre.
    const glm::ivec2 ret_lo = px({-kReticleHalfWidth, kReticleHalfHeight});
    const glm::ivec2 ret_hi = px({kReticleHalfWidth, -kReticleHalfHeight});
    EXPECT_GT(f.lit(ret_lo, ret_hi, 1), 40) << "reticle";
    // The level: horizon, mountains and obstacles light the band around the horizon line
    // across the whole width.
    for (int x0 = 0; x0 < kGameW; x0 += kGameW / 4) {
        EXPECT_GT(f.lit({x0, kGameH * 2 / 5}, {x0 + kGameW / 4, kGameH * 3 / 5}, 1), 40)
            << "horizon band from x " << x0;
    }
    // Nothing fills the ground near the bottom edge.
    EXPECT_LT(f.lit({0, kGameH * 9 / 10}, {kGameW, kGameH}, 1), kGameW * kGameH / 100) << "ground";
}
