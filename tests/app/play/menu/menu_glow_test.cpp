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
#include "support/hud_frames.h"
#include "support/tree_paths.h"

namespace bz::app::menu {
namespace {

constexpr int kGlowW = 1280, kGlowH = 720;
// Past the beam's own quad (half-width and lengthened ends, a few pixels at 720 lines).
constexpr float kClearPx = 8.0f;

// Whether each pixel lies within kClearPx of any of `hud`'s lines.
std::vector<bool> near_lines(const std::vector<scene::HudLine>& hud) {
    const std::vector<float> d = test::hud_line_distance(hud, kGlowW, kGlowH, kClearPx + 1.0f);
    std::vector<bool> near(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) near[i] = d[i] <= kClearPx;
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
                const scene::FrameList bare = game.frame(1.0, double(kGlowW) / kGlowH);
                scene::FrameList with_menu = bare;
                std::vector<scene::HudLine> menu_lines;
                menus.draw(menu_lines, font, double(kGlowW) / kGlowH, 0);
                ASSERT_FALSE(menu_lines.empty());
                with_menu.hud.insert(with_menu.hud.end(), menu_lines.begin(), menu_lines.end());

                render::Renderer a(settings, kGlowW, kGlowH, gl::TimingMethod::off);
                a.render(bare, game.meshes(), render::Renderer::kOffscreen);
                const std::vector<std::uint8_t> plain = a.read_color();
                render::Renderer b(settings, kGlowW, kGlowH, gl::TimingMethod::off);
                b.render(with_menu, game.meshes(), render::Renderer::kOffscreen);
                const std::vector<std::uint8_t> shown = b.read_color();
                write_png(out / ("menu_" + label + ".png"), Image{kGlowW, kGlowH, 4, shown});

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
