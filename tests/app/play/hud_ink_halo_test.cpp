// The ink HUD theme's paper halo (shaders/hud/hud.frag writes it into the lines target's alpha,
// shaders/styles/ink_composite.frag lays it under the ink): on a game frame at 1280x720 with
// the play HUD, in every style with the ink theme, the pixels just past a HUD stroke's ink are
// paper, whatever the fill or stroke behind them, and the HUD changes nothing farther than its
// beam and its halo reach. Frames go to build/test-out/hud_ink_halo_<style>.png.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "app/play/play_overlay.h"
#include "core/image_io.h"
#include "render/renderer.h"
#include "scene/style_table.h"
#include "support/gl_test.h"
#include "support/hud_frames.h"
#include "support/tree_paths.h"

namespace {

constexpr int kW = 1280, kH = 720;

std::vector<std::uint8_t> draw(const bz::scene::FrameList& f,
                               const bz::scene::MeshLibrary& meshes) {
    bz::render::Renderer r(bz::render::preset("balanced"), kW, kH, bz::gl::TimingMethod::off);
    r.render(f, meshes, bz::render::Renderer::kOffscreen);
    return r.read_color();
}

bool near_colour(const std::uint8_t* px, const glm::vec3& colour, int tolerance) {
    for (int c = 0; c < 3; ++c) {
        const int want = static_cast<int>(std::lround(std::clamp(colour[c], 0.0f, 1.0f) * 255.0f));
        if (std::abs(int{px[c]} - want) > tolerance) return false;
    }
    return true;
}

// Bright HUD strokes across the band of the screen where the level's fills and strokes stand
// (pixels, y down), so that the halo is tested over them and not only over the paper.
void add_strokes_across_the_scene(std::vector<bz::scene::HudLine>& hud) {
    const auto at = [](float x, float y) {
        return glm::vec2((x + 0.5f - kW * 0.5f) / (kH * 0.5f),
                         (kH * 0.5f - y - 0.5f) / (kH * 0.5f));
    };
    const glm::vec3 red(1.0f, 0.2f, 0.2f);
    for (int i = 0; i < 8; ++i) {
        const float y = 250.0f + 25.0f * static_cast<float>(i);
        hud.push_back({at(20.0f, y), at(kW - 20.0f, y), red, 1.0f});
    }
    for (int i = 0; i < 12; ++i) {
        const float x = 50.0f + 105.0f * static_cast<float>(i);
        hud.push_back({at(x, 240.0f), at(x, 440.0f), red, 1.0f});
    }
}

using HudInkHaloTest = bz::test::GlTest;

TEST_F(HudInkHaloTest, PaperRimsTheInkAndEndsWithinItsReach) {
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    const auto game_ptr = bz::test::game_in_play(font);
    bz::game::Game& game = *game_ptr;
    bz::app::PlayOverlay overlay(font);
    overlay.notify("style toon");
    const auto out = bz::test::binary_dir() / "test-out";
    std::filesystem::create_directories(out);
    int inked = 0;
    for (const bz::scene::Style style : bz::scene::all_styles()) {
        const bz::scene::StyleDef& def = bz::scene::style_entry(style).def;
        if (!def.hud.ink) continue;
        ++inked;
        const std::string name(bz::scene::style_name(style));
        SCOPED_TRACE(name);
        bz::scene::FrameList f = game.frame(1.0, double(kW) / kH);
        f.style = style;
        const bz::scene::FrameList bare = f;
        overlay.draw(f.hud, double(kW) / kH);
        add_strokes_across_the_scene(f.hud);
        const auto with_hud = draw(f, game.meshes());
        const auto without = draw(bare, game.meshes());
        bz::write_png(out / ("hud_ink_halo_" + name + ".png"), bz::Image{kW, kH, 4, with_hud});

        // The ink's core ends about 1.5 px from a stroke's spine at 720 lines; the halo reaches
        // halo_px past the beam (hud.frag's quad: the beam's half-width + halo_px).
        const float halo = def.hud.halo_px;
        const auto strong = bz::test::hud_line_distance(f.hud, kW, kH, 16.0f, 0.8f);
        const auto any = bz::test::hud_line_distance(f.hud, kW, kH, 16.0f, 0.0f);
        std::size_t rim = 0, rim_paper = 0, far = 0, far_changed = 0, behind_not_paper = 0;
        for (std::size_t i = 0; i < any.size(); ++i) {
            const std::uint8_t* px = &with_hud[i * 4];
            const std::uint8_t* under = &without[i * 4];
            // Just past the ink of a bright stroke, no fainter one nearer: paper.
            if (strong[i] >= 2.0f && strong[i] <= 0.5f + halo && any[i] >= 2.0f) {
                ++rim;
                rim_paper += near_colour(px, def.background, 6) ? 1 : 0;
                behind_not_paper += near_colour(under, def.background, 24) ? 0 : 1;
            }
            // Past the widest beam (3 px) and the halo, with a pixel to spare: untouched.
            if (any[i] > 4.0f + halo) {
                ++far;
                far_changed +=
                    (px[0] != under[0] || px[1] != under[1] || px[2] != under[2]) ? 1 : 0;
            }
        }
        std::printf(
            "HUD ink halo %-10s rim %zu px (%zu over fills or strokes), %.1f %% paper; "
            "%zu of %zu pixels beyond it changed\n",
            name.c_str(), rim, behind_not_paper,
            100.0 * static_cast<double>(rim_paper) /
                static_cast<double>(std::max<std::size_t>(rim, 1)),
            far_changed, far);
        EXPECT_GT(rim, 1000u);
        EXPECT_GT(behind_not_paper, 50u);  // the rim crosses something that is not paper
        EXPECT_GE(static_cast<double>(rim_paper), 0.97 * static_cast<double>(rim));
        EXPECT_GT(far, std::size_t{kW} * kH / 2);
        EXPECT_EQ(far_changed, 0u);
    }
    EXPECT_GE(inked, 5);  // toon, sketch, pop-art, halo, technical
}

}  // namespace
