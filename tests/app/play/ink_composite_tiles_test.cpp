// The filled styles' composite (render/styles/pass_ink_composite.cpp) copies the canvas to the
// target and runs the HUD's ink and paper halo only over the screen tiles the HUD lit, grown
// by the halo's reach. The frame must be the one the every-pixel composite draws
// (RenderSettings::sparse_composite off): a real game frame at 1280x720 with the play HUD, a
// notice and the frame-rate footer, in every filled style, and with the HUD in the tile
// corners and screen edges, where a tile grown too little would cut a halo off. Frames go to
// build/test-out/ink_tiles_<style>.png. The halo style's paper layer (pass_halo.cpp) runs
// only over the tiles its halo quads marked, under the same switch: it is compared too.
#include <gtest/gtest.h>

#include <algorithm>
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

constexpr int kInkW = 1280, kInkH = 720;

struct Difference {
    int worst = 0;            // the largest difference of any channel
    std::size_t pixels = 0;   // pixels that differ at all
    std::size_t changed = 0;  // pixels the HUD changed (the dense frame differs from paper-only)
};

Difference compare(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                   const std::vector<std::uint8_t>& no_hud) {
    Difference d;
    for (std::size_t p = 0; p + 3 < a.size(); p += 4) {
        bool differs = false, changed = false;
        for (std::size_t c = 0; c < 4; ++c) {
            const int v = std::abs(int{a[p + c]} - int{b[p + c]});
            d.worst = std::max(d.worst, v);
            differs = differs || v > 0;
            changed = changed || b[p + c] != no_hud[p + c];
        }
        d.pixels += differs ? 1 : 0;
        d.changed += changed ? 1 : 0;
    }
    return d;
}

std::vector<std::uint8_t> draw(bz::render::RenderSettings settings, const bz::scene::FrameList& f,
                               const bz::scene::MeshLibrary& meshes) {
    bz::render::Renderer r(settings, kInkW, kInkH, bz::gl::TimingMethod::off);
    r.render(f, meshes, bz::render::Renderer::kOffscreen);
    return r.read_color();
}

// HUD lines (HUD units: y from -1 to 1, x scaled by the aspect) at the screen's corners and
// edges and across tile corners.
void add_edge_lines(std::vector<bz::scene::HudLine>& hud) {
    const auto at = [](float x, float y) {
        return glm::vec2((x + 0.5f - kInkW * 0.5f) / (kInkH * 0.5f),
                         (kInkH * 0.5f - y - 0.5f) / (kInkH * 0.5f));
    };
    const glm::vec3 red(1.0f, 0.2f, 0.2f);
    hud.push_back({at(0, 0), at(kInkW - 1, 0), red, 1.0f});
    hud.push_back({at(kInkW - 1, 0), at(kInkW - 1, kInkH - 1), red, 1.0f});
    hud.push_back({at(64, 400), at(64, 400), red, 1.0f});    // a dot on a tile corner
    hud.push_back({at(95, 300), at(97, 300), red, 0.05f});   // faint, at a tile's edge
    hud.push_back({at(300, 500), at(700, 650), red, 0.7f});  // diagonal across many tiles
    // Short strokes from 10 px before to 9 px past a tile's edge (32 px tiles), across and
    // along: their halo reaches into the next tile by every amount the marks must cover.
    for (int i = 0; i < 20; ++i) {
        const float x = static_cast<float>(64 * i + 32 + (i - 10));
        hud.push_back({at(x, 660), at(x, 668), red, 1.0f});
        const float y = static_cast<float>(32 * (i % 10) + 32 + (i - 10));
        const float x0 = static_cast<float>(900 + 16 * (i / 10));
        hud.push_back({at(x0, y), at(x0 + 6.0f, y), red, 1.0f});
    }
}

using InkCompositeTilesTest = bz::test::GlTest;

TEST_F(InkCompositeTilesTest, EveryFilledStyleWithTheHudMatchesTheEveryPixelComposite) {
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    const auto game_ptr = bz::test::game_in_play(font);
    bz::game::Game& game = *game_ptr;
    ASSERT_EQ(game.screen(), bz::game::Screen::playing);
    bz::app::PlayOverlay overlay(font);
    overlay.notify("style halo");
    overlay.set_footer("58 FPS  17.2 MS");

    const auto out = bz::test::binary_dir() / "test-out";
    std::filesystem::create_directories(out);
    int filled = 0;
    for (const bz::scene::Style style : bz::scene::all_styles()) {
        const bz::scene::StyleDef& def = bz::scene::style_entry(style).def;
        if (def.fill == bz::scene::FillPass::none) continue;
        ++filled;
        const std::string name(bz::scene::style_name(style));
        SCOPED_TRACE(name);
        bz::scene::FrameList f = game.frame(1.0, double(kInkW) / kInkH);
        f.style = style;
        bz::scene::FrameList bare = f;  // no HUD: what the canvas alone gives
        overlay.draw(f.hud, double(kInkW) / kInkH);
        add_edge_lines(f.hud);
        bz::render::RenderSettings settings = bz::render::preset("balanced");
        settings.sparse_composite = true;
        const auto tiles = draw(settings, f, game.meshes());
        const auto bare_tiles = draw(settings, bare, game.meshes());
        settings.sparse_composite = false;
        const auto dense = draw(settings, f, game.meshes());
        const auto bare_dense = draw(settings, bare, game.meshes());
        bz::write_png(out / ("ink_tiles_" + name + ".png"), bz::Image{kInkW, kInkH, 4, tiles});

        const Difference d = compare(tiles, dense, bare_dense);
        std::printf("ink composite %-10s worst %d, %zu pixels differ, HUD changed %zu pixels\n",
                    name.c_str(), d.worst, d.pixels, d.changed);
        EXPECT_EQ(d.worst, 0);
        EXPECT_EQ(d.pixels, 0u);
        // The HUD (with its halo) changes a real share of the frame, not all of it: the
        // comparison covers what the tiles must reach.
        EXPECT_GT(d.changed, std::size_t{kInkW} * kInkH / 200);
        EXPECT_LT(d.changed, std::size_t{kInkW} * kInkH / 2);
        // Without a HUD the copy is the canvas: the same frame as the every-pixel composite.
        EXPECT_EQ(compare(bare_tiles, bare_dense, bare_dense).worst, 0);
    }
    EXPECT_GE(filled, 5);  // toon, sketch, pop-art, halo, technical
}

}  // namespace
