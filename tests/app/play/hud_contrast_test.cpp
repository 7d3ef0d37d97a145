// The HUD reads in every style: a real game frame at 1280x720 with the play HUD, a notice and
// the frame-rate footer, drawn in each style. Where the HUD's text and marks run (the centre
// pixels of its lines of intensity >= 0.6, from the HUD's own geometry; the radar's fading
// sweep trail is dimmer by design) and the pixels around them (3 to 5 px from any HUD line)
// are compared per 32x32 tile: WCAG contrast ratio of their mean relative luminances. The
// reticle's box is left out: it is an aiming mark over the scene, not text. Every style, in
// both beam looks for the dark ones (whose HUD is drawn after the bloom, so that its glow
// does not lift the ring: render/beam/pass_hud.cpp), and text sizes 1x and 2x, must reach
// 4.5:1 in every tile. Frames go to build/test-out/hud_<style>_<beam>_<scale>x.png.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/play/play_overlay.h"
#include "core/image_io.h"
#include "game/default_level.h"
#include "game/game.h"
#include "render/renderer.h"
#include "scene/style_table.h"
#include "support/gl_test.h"
#include "support/hud_frames.h"
#include "support/tree_paths.h"

namespace {

constexpr int kHudW = 1280, kHudH = 720, kTile = 32;

float linear(std::uint8_t c) {
    const float v = static_cast<float>(c) / 255.0f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float luminance(const std::vector<std::uint8_t>& rgba, std::size_t i) {
    return 0.2126f * linear(rgba[i * 4]) + 0.7152f * linear(rgba[i * 4 + 1]) +
           0.0722f * linear(rgba[i * 4 + 2]);
}

// Each pixel's distance to the nearest HUD line (capped at 8 px).
std::vector<float> hud_distance(const std::vector<bz::scene::HudLine>& hud, float min_intensity) {
    return bz::test::hud_line_distance(hud, kHudW, kHudH, 8.0f, min_intensity);
}

struct Contrast {
    float worst = 1e9f;  // the lowest tile's ratio
    float median = 0.0f;
    int tiles = 0;
};

Contrast hud_contrast(const std::vector<std::uint8_t>& rgba, const std::vector<float>& text,
                      const std::vector<float>& dist) {
    std::vector<float> ratios;
    for (int ty = 0; ty < kHudH; ty += kTile) {
        for (int tx = 0; tx < kHudW; tx += kTile) {
            const bool reticle = std::abs(tx + kTile / 2 - kHudW / 2) < 100 &&
                                 std::abs(ty + kTile / 2 - kHudH / 2) < 100;
            if (reticle) continue;
            double core = 0.0, ring = 0.0;
            int nc = 0, nr = 0;
            for (int y = ty; y < std::min(ty + kTile, kHudH); ++y) {
                for (int x = tx; x < std::min(tx + kTile, kHudW); ++x) {
                    const std::size_t i = static_cast<std::size_t>(y) * kHudW + x;
                    if (text[i] <= 0.5f) {
                        core += luminance(rgba, i);
                        ++nc;
                    } else if (dist[i] >= 3.0f && dist[i] <= 5.0f) {
                        ring += luminance(rgba, i);
                        ++nr;
                    }
                }
            }
            if (nc < 12 || nr < 24) continue;
            const double a = core / nc, b = ring / nr;
            ratios.push_back(static_cast<float>((std::max(a, b) + 0.05) / (std::min(a, b) + 0.05)));
            if (std::getenv("BZ_HUD_TILES"))
                std::printf("tile %d,%d core %.3f ring %.3f ratio %.2f\n", tx, ty, a, b,
                            ratios.back());
        }
    }
    Contrast c;
    c.tiles = static_cast<int>(ratios.size());
    if (ratios.empty()) return c;
    std::sort(ratios.begin(), ratios.end());
    c.worst = ratios.front();
    c.median = ratios[ratios.size() / 2];
    return c;
}

using HudContrastTest = bz::test::GlTest;

TEST_F(HudContrastTest, HudAndNoticesReachWcagContrastInEveryStyle) {
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    const auto game_ptr = bz::test::game_in_play(font);
    bz::game::Game& game = *game_ptr;
    ASSERT_EQ(game.screen(), bz::game::Screen::playing);

    const auto out = bz::test::binary_dir() / "test-out";
    std::filesystem::create_directories(out);
    for (const float scale : {1.0f, 2.0f}) {
        bz::app::PlayOverlay overlay(font);
        overlay.set_text_scale(scale);
        overlay.notify("style halo");
        overlay.set_footer("58 FPS  17.2 MS");
        overlay.set_errors(bz::app::ErrorKind::model, {"models/tank.obj:12:3: no such file"});
        game.set_text_scale(scale);
        for (const std::string& beam : bz::render::beam_look_names()) {
            bz::render::RenderSettings settings = bz::render::preset("balanced");
            settings.beam = bz::render::beam_look(beam);
            for (const bz::scene::Style style : bz::scene::all_styles()) {
                // The beam looks only change the dark styles; the paper ones are drawn once.
                if (beam != bz::render::kDefaultBeamLook &&
                    bz::scene::style_entry(style).def.hud.ink)
                    continue;
                const std::string name = std::string(bz::scene::style_name(style)) + "_" + beam +
                                         "_" + std::to_string(static_cast<int>(scale)) + "x";
                SCOPED_TRACE(name);
                bz::scene::FrameList f = game.frame(1.0, double(kHudW) / kHudH);
                overlay.draw(f.hud, double(kHudW) / kHudH);
                f.style = style;
                bz::render::Renderer r(settings, kHudW, kHudH, bz::gl::TimingMethod::off);
                r.render(f, game.meshes(), bz::render::Renderer::kOffscreen);
                const std::vector<std::uint8_t> rgba = r.read_color();
                bz::write_png(out / ("hud_" + name + ".png"), bz::Image{kHudW, kHudH, 4, rgba});
                const Contrast c =
                    hud_contrast(rgba, hud_distance(f.hud, 0.6f), hud_distance(f.hud, 0.0f));
                std::printf("HUD contrast %-23s worst tile %.2f, median %.2f, %d tiles\n",
                            name.c_str(), c.worst, c.median, c.tiles);
                EXPECT_GT(c.tiles, 20);
                EXPECT_GE(c.worst, 4.5f);
            }
        }
    }
}

}  // namespace
