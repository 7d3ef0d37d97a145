// High scores are kept per level: the menu's table names whose it is.
#include <gtest/gtest.h>

#include "app/play/menu/play_menus.h"

namespace bz::app::menu {
namespace {

TEST(HighScoresPerLevelPage, TheTableNamesItsLevel) {
    platform::Settings settings;
    game::HighScoreTable scores = game::HighScoreTable::defaults();
    Env env;
    env.settings = &settings;
    env.presets = {"balanced"};
    env.high_scores = &scores;
    env.high_scores_level = "EASY ONE";
    PlayMenus menus(env);
    menus.set_context(Context::title);
    menus.open_page(PlayMenus::Screen::high_scores);
    const Page p = menus.page();
    ASSERT_GE(p.rows.size(), 3u);
    EXPECT_EQ(p.rows[0].label, "EASY ONE");
    EXPECT_FALSE(p.rows[0].selectable);
    EXPECT_EQ(p.rows[1].label, "1.  EDR");
}

}  // namespace
}  // namespace bz::app::menu
