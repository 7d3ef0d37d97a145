// Menus stay clean on the dark looks: the menu's lines add nothing to the picture away from
// themselves. Each page is drawn over the title screen's game frame, at 1280x720, in both
// beam looks and at text sizes 1x and 2x, and compared with the same frame without the menu:
// every pixel more than kClearPx from any menu line must be the same (a wide bloom of the
// highlighted rows left a green haze of 23-40/255 up to ~200 px around the lists with mame).
// Frames go to build/test-out/menu_<page>_<beam>_<scale>x.png.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/play/menu/play_menus.h"
#include "core/image_io.h"
#include "game/default_level.h"
#include "game/game.h"
#include "render/renderer.h"
#include "support/gl_test.h"
#include "support/tree_paths.h"

namespace bz::app::menu {
namespace {

constexpr int kW = 1280, kH = 720;
// Past the beam's own quad (half-width and lengthened ends, a few pixels at 720 lines).
constexpr float kClearPx = 8.0f;

// Whether each pixel lies within kClearPx of any of `hud`'s lines.
std::vector<bool> near_lines(const std::vector<scene::HudLine>& hud) {
    std::vector<bool> near(static_cast<std::size_t>(kW) * kH, false);
    const auto px = [](glm::vec2 u) {
        return glm::vec2(kW * 0.5f + u.x * kH * 0.5f, kH * 0.5f - u.y * kH * 0.5f);
    };
    const int r = static_cast<int>(kClearPx) + 1;
    for (const scene::HudLine& l : hud) {
        const glm::vec2 a = px(l.a), b = px(l.b);
        const int x0 = std::max(0, static_cast<int>(std::min(a.x, b.x)) - r);
        const int x1 = std::min(kW - 1, static_cast<int>(std::max(a.x, b.x)) + r);
        const int y0 = std::max(0, static_cast<int>(std::min(a.y, b.y)) - r);
        const int y1 = std::min(kH - 1, static_cast<int>(std::max(a.y, b.y)) + r);
        const glm::vec2 ab = b - a;
        const float len2 = std::max(glm::dot(ab, ab), 1e-6f);
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                const float t = std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f);
                if (glm::length(p - (a + t * ab)) <= kClearPx)
                    near[static_cast<std::size_t>(y) * kW + x] = true;
            }
        }
    }
    return near;
}

using MenuGlowTest = test::GlTest;

TEST_F(MenuGlowTest, MenusLeaveNoHazeAroundTheirListsInEitherBeamLook) {
    const scene::VectorFont font = scene::VectorFont::load_default();
    game::GameOptions options;
    options.seed = 5;
    game::Game game(game::default_level(), options, &font);
    for (int i = 0; i < 30; ++i) game.tick(game::TickCommand{});

    const auto out = test::binary_dir() / "test-out";
    std::filesystem::create_directories(out);
    const std::pair<PlayMenus::Screen, const char*> pages[] = {
        {PlayMenus::Screen::title, "title"},
        {PlayMenus::Screen::controls, "controls"},
        {PlayMenus::Screen::keys, "keys"}};
    for (const std::string& beam : render::beam_look_names()) {
        render::RenderSettings settings = render::preset("balanced");
        settings.beam = render::beam_look(beam);
        for (const float scale : {1.0f, 2.0f}) {
            platform::Settings player;
            player.ui_scale = scale;
            Env env;
            env.settings = &player;
            env.presets = {"fast", "balanced", "high"};
            PlayMenus menus(env);
            menus.set_context(Context::title);
            for (const auto& [screen, name] : pages) {
                const std::string label =
                    std::string(name) + "_" + beam + "_" + std::to_string(int(scale)) + "x";
                SCOPED_TRACE(label);
                if (screen != PlayMenus::Screen::title) menus.open_page(screen);
                const scene::FrameList bare = game.frame(1.0, double(kW) / kH);
                scene::FrameList with_menu = bare;
                std::vector<scene::HudLine> menu_lines;
                menus.draw(menu_lines, font, double(kW) / kH, 0);
                ASSERT_FALSE(menu_lines.empty());
                with_menu.hud.insert(with_menu.hud.end(), menu_lines.begin(), menu_lines.end());

                render::Renderer a(settings, kW, kH, gl::TimingMethod::off);
                a.render(bare, game.meshes(), render::Renderer::kOffscreen);
                const std::vector<std::uint8_t> plain = a.read_color();
                render::Renderer b(settings, kW, kH, gl::TimingMethod::off);
                b.render(with_menu, game.meshes(), render::Renderer::kOffscreen);
                const std::vector<std::uint8_t> shown = b.read_color();
                write_png(out / ("menu_" + label + ".png"), Image{kW, kH, 4, shown});

                const std::vector<bool> near = near_lines(menu_lines);
                int max_diff = 0, differing = 0, far = 0, lit_near = 0;
                for (std::size_t i = 0; i < near.size(); ++i) {
                    int d = 0;
                    for (int c = 0; c < 3; ++c)
                        d = std::max(d, std::abs(int(shown[i * 4 + c]) - int(plain[i * 4 + c])));
                    if (near[i]) {
                        lit_near += d > 0;
                        continue;
                    }
                    ++far;
                    max_diff = std::max(max_diff, d);
                    differing += d > 0;
                }
                std::printf("menu %-22s away from the menu: max diff %d, %d of %d pixels differ\n",
                            label.c_str(), max_diff, differing, far);
                EXPECT_GT(lit_near, 500);  // the menu is drawn
                EXPECT_LE(max_diff, 1);
                EXPECT_EQ(differing, 0);
            }
        }
    }
}

}  // namespace
}  // namespace bz::app::menu
