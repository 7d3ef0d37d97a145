// Hostile level names and descriptions on the menus: a 64-character name, a 300-character
// description and a broken file with a 250-character name, in the player's level folder. At
// every text size and screen shape, every stroke of the title menu and the level list stays
// on the screen (x within the aspect, y within -1..1), so no name pushes the others off.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "app/play/menu/level_list.h"
#include "app/play/menu/menu_page.h"
#include "app/play/menu/play_menus.h"
#include "game/hud/hud_layout.h"
#include "support/scratch_dir.h"

namespace bz::app::menu {
namespace {

const scene::VectorFont& font() {
    static const scene::VectorFont f = scene::VectorFont::load_default();
    return f;
}

// The first stroke end outside the screen, as text, or "" when all are inside.
std::string first_outside(const std::vector<scene::HudLine>& lines, double aspect) {
    const auto a = static_cast<float>(aspect) + 1e-4f;
    for (const scene::HudLine& l : lines) {
        for (const glm::vec2 p : {l.a, l.b}) {
            if (p.x < -a || p.x > a || p.y < -1.0001f || p.y > 1.0001f)
                return std::to_string(p.x) + "," + std::to_string(p.y);
        }
    }
    return {};
}

TEST(MenuBounds, HostileLevelNamesStayOnTheScreenAtEveryScaleAndShape) {
    const test::ScratchDir dir("bz_menu_bounds");
    const auto shipped = dir.path() / "shipped";
    const auto user = dir.path() / "user";
    std::filesystem::create_directories(shipped);
    std::filesystem::create_directories(user);
    const std::string wide_name(64, 'W');
    std::string description;
    while (description.size() < 290) description += "MMMM WWWW ";
    std::ofstream(user / "long.toml")
        << "version = 1\nname = \"" << wide_name << "\"\ndescription = \"" << description << "\"\n";
    std::ofstream(user / (std::string(250, 'w') + ".toml")) << "version = 1\nname = \n";
    std::ofstream(shipped / "plain.toml") << "version = 1\nname = \"Plain\"\n";

    platform::Settings settings;
    game::HighScoreTable scores = game::HighScoreTable::defaults();
    Env env;
    env.settings = &settings;
    env.presets = {"fast", "balanced", "high"};
    env.levels = find_levels(shipped, user);
    ASSERT_EQ(env.levels.size(), 3u);
    env.current_level = user / "long.toml";  // the title menu's LEVEL row names it
    env.high_scores = &scores;

    for (const float scale : {1.0f, 1.5f, 2.0f}) {
        for (const double aspect : {4.0 / 3.0, 16.0 / 9.0, 1.0}) {
            settings.ui_scale = scale;
            PlayMenus menus(env);
            menus.set_context(Context::title);
            std::vector<scene::HudLine> lines;
            menus.draw(lines, font(), aspect, 0);
            ASSERT_FALSE(lines.empty());
            EXPECT_EQ(first_outside(lines, aspect), "")
                << "title menu, scale " << scale << ", aspect " << aspect;
            // The level list, with each level selected in turn (its description shows).
            menus.handle(platform::MenuKey::down);
            menus.handle(platform::MenuKey::confirm);
            ASSERT_EQ(menus.screen(), PlayMenus::Screen::levels);
            for (std::size_t i = 0; i < env.levels.size(); ++i) {
                lines.clear();
                menus.draw(lines, font(), aspect, 0);
                EXPECT_EQ(first_outside(lines, aspect), "")
                    << "level list, row " << i << ", scale " << scale << ", aspect " << aspect;
                menus.handle(platform::MenuKey::down);
            }
        }
    }
}

// Seen under Xvfb: at 2x the pause menu showed two of its four rows over "MORE BELOW", which
// ran into the frame-rate readout. Now its title rises with the rows, every row shows, and no
// page's last row reaches down into the readout's strip, at any text size.
TEST(MenuBounds, PauseShowsEveryRowAndNoRowReachesTheReadout) {
    Page pause;
    pause.title = "PAUSED";
    pause.under_band = true;
    for (const char* label : {"RESUME", "OPTIONS", "CONTROLS", "QUIT TO TITLE"}) {
        Row r;
        r.label = label;
        pause.rows.push_back(r);
    }
    Page title = pause;
    title.under_band = false;
    title.big_title = true;
    for (const char* label : {"LEVEL", "HIGH SCORES"}) {
        Row r;
        r.label = label;
        title.rows.push_back(r);
    }
    for (const float scale : {1.0f, 1.25f, 1.5f, 1.75f, 2.0f}) {
        for (const double aspect : {4.0 / 3.0, 16.0 / 9.0}) {
            const auto a = static_cast<float>(aspect);
            for (const Page* page : {&pause, &title}) {
                const Placement pl = place(font(), *page, 0, aspect, scale);
                EXPECT_EQ(pl.window.count, page->rows.size())
                    << page->title << " scrolls at " << scale << ", aspect " << aspect;
                const float readout_top = game::hud::readout_box(a, scale).max.y;
                for (const PlacedRow& r : pl.rows) {
                    EXPECT_GT(r.y - 0.38f * r.text_height, readout_top)
                        << page->title << " row " << r.row << " at " << scale;
                }
                // The title stays under the HUD band and above the first row.
                EXPECT_LT(pl.layout.title_y + 0.09f * scale, game::hud::kBandBottom + 0.3f);
                EXPECT_GT(pl.layout.title_y, pl.layout.rows_top);
            }
        }
    }
}

}  // namespace
}  // namespace bz::app::menu
