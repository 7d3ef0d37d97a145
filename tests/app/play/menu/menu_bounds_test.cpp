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
#include "app/play/play_overlay.h"
#include "game/hud/hud_layout.h"
#include "support/default_font.h"
#include "support/scratch_dir.h"

namespace bz::app::menu {
namespace {

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
            menus.draw(lines, bz::test::default_font(), aspect, 0);
            ASSERT_FALSE(lines.empty());
            EXPECT_EQ(first_outside(lines, aspect), "")
                << "title menu, scale " << scale << ", aspect " << aspect;
            // The level list, with each level selected in turn (its description shows).
            menus.handle(platform::MenuKey::down);
            menus.handle(platform::MenuKey::confirm);
            ASSERT_EQ(menus.screen(), PlayMenus::Screen::levels);
            for (std::size_t i = 0; i < env.levels.size(); ++i) {
                lines.clear();
                menus.draw(lines, bz::test::default_font(), aspect, 0);
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
                const Placement pl = place(bz::test::default_font(), *page, 0, aspect, scale);
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

namespace bz::app::menu {
namespace {

struct YRange {
    float lo = 1e9f, hi = -1e9f;
};
YRange y_range(const std::vector<scene::HudLine>& lines) {
    YRange r;
    for (const scene::HudLine& l : lines) {
        r.lo = std::min({r.lo, l.a.y, l.b.y});
        r.hi = std::max({r.hi, l.a.y, l.b.y});
    }
    return r;
}

// Seen in the screenshots: a notice ("screenshot ...") in the notice strip crossed the title
// menu's last row at 2x, since a menu's rows reach down to the readout's strip. While a menu
// is open the newest notice takes the footer line in place of the key hints: on every page's
// first screen, at every text size and screen shape, the notice lies in the footer, below
// every stroke of the menu, and the menu leaves the footer to it.
TEST(MenuBounds, ANoticeOverAMenuTakesTheFooterAndCrossesNoRow) {
    platform::Settings settings;
    game::HighScoreTable scores = game::HighScoreTable::defaults();
    Env env;
    env.settings = &settings;
    env.presets = {"fast", "balanced", "high"};
    env.high_scores = &scores;
    for (const Context context : {Context::title, Context::paused}) {
        for (const float scale : {1.0f, 1.5f, 2.0f}) {
            for (const double aspect : {4.0 / 3.0, 16.0 / 9.0, 21.0 / 9.0}) {
                settings.ui_scale = scale;
                PlayMenus menus(env);
                menus.set_context(context);
                PlayOverlay overlay(bz::test::default_font());
                overlay.set_text_scale(scale);
                overlay.set_footer("60 FPS  16.7 MS  WORST 18.0 MS");
                overlay.notify("screenshot beamzone-20261127-101500-000.png");
                overlay.set_notice_place(PlayOverlay::NoticePlace::footer);
                ASSERT_TRUE(overlay.notice_in_footer());

                std::vector<scene::HudLine> menu_lines, overlay_lines;
                menus.draw(menu_lines, bz::test::default_font(), aspect, 0, FooterLine::overlay);
                overlay.draw(overlay_lines, aspect);
                const auto a = static_cast<float>(aspect);
                const game::hud::Box footer = game::hud::footer_box(a);
                const game::hud::Box readout = game::hud::readout_box(a, scale);
                std::vector<scene::HudLine> notice;
                for (const scene::HudLine& l : overlay_lines) {
                    if (readout.contains(l.a) && readout.contains(l.b)) continue;
                    EXPECT_TRUE(footer.contains(l.a) && footer.contains(l.b))
                        << "notice outside the footer at " << scale << ", " << aspect;
                    notice.push_back(l);
                }
                ASSERT_FALSE(notice.empty());
                const YRange m = y_range(menu_lines);
                EXPECT_GT(m.lo, footer.max.y) << "the menu draws in the footer at " << scale;
                EXPECT_LT(y_range(notice).hi, m.lo);
                EXPECT_EQ(first_outside(notice, aspect), "");

                // The strip the notice left: at 2x it would have crossed the menu's rows,
                // which is why the footer takes it.
                if (scale == 2.0f) {
                    PlayOverlay strip(bz::test::default_font());
                    strip.set_text_scale(scale);
                    strip.notify("screenshot beamzone-20261127-101500-000.png");
                    std::vector<scene::HudLine> in_strip;
                    strip.draw(in_strip, aspect);
                    EXPECT_GT(y_range(in_strip).hi, m.lo) << "the strip no longer reaches the "
                                                             "rows: the footer rule may go";
                }
            }
        }
    }
}

}  // namespace
}  // namespace bz::app::menu
