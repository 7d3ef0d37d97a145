// The arcade machine's switches over a level's rules: what they change, how they are named,
// that replays carry them and that high-score tables are kept apart by them.
#include "game/difficulty/arcade_rules.h"

#include <gtest/gtest.h>

#include "game/default_level.h"
#include "game/difficulty/autopilot.h"
#include "game/game.h"
#include "game/records/level_rules.h"
#include "game/records/replay.h"

namespace bz::game {
namespace {

TEST(ArcadeRules, UnsetRulesKeepTheLevelsOwn) {
    const level::Level lv = default_level();
    const level::Level same = with_arcade_rules(lv, {});
    EXPECT_EQ(same.player_lives, lv.player_lives);
    EXPECT_EQ(same.enemies.missile_score, lv.enemies.missile_score);
    EXPECT_EQ(same.bonus_scores, lv.bonus_scores);
    EXPECT_EQ(level_rules_hash(same), level_rules_hash(lv));
    EXPECT_EQ(arcade_label({}), "");
}

TEST(ArcadeRules, EachSwitchChangesItsRuleAndTheRulesHash) {
    const level::Level lv = default_level();
    ArcadeRules r;
    r.lives = 5;
    r.missile_score = 30000;
    r.bonus_score = 50000;
    const level::Level a = with_arcade_rules(lv, r);
    EXPECT_EQ(a.player_lives, 5);
    EXPECT_EQ(a.enemies.missile_score, 30000);
    EXPECT_EQ(a.bonus_scores, (std::vector<int>{50000, kArcadeSecondBonus}));
    EXPECT_NE(level_rules_hash(a), level_rules_hash(lv));
    EXPECT_EQ(arcade_label(r), "5 TANKS, MISSILES 30000, BONUS 50000");
    ArcadeRules none;
    none.bonus_score = 0;
    EXPECT_TRUE(with_arcade_rules(lv, none).bonus_scores.empty());
    EXPECT_EQ(arcade_label(none), "NO BONUS");
}

TEST(ArcadeRules, GamesStartWithThemAndReplaysCarryThem) {
    GameOptions o;
    o.attract = false;
    o.record = true;
    o.seed = 9;
    o.arcade.lives = 2;
    o.arcade.missile_score = 5000;
    o.arcade.bonus_score = 0;
    Game g(default_level(), o);
    ASSERT_NE(g.world(), nullptr);
    EXPECT_EQ(g.world()->lives(), 2);
    EXPECT_TRUE(g.world()->bonus_scores().empty());
    for (int i = 0; i < 60 * 40 && g.screen() == Screen::playing; ++i) {
        g.tick(autopilot(*g.world()));
    }
    const auto rec = g.recording();
    ASSERT_TRUE(rec.has_value());
    EXPECT_EQ(rec->header.lives, 2);
    EXPECT_EQ(rec->header.missile_score, 5000);
    EXPECT_EQ(rec->header.bonus_score, 0);
    const std::string text = replay::serialise(*rec);
    EXPECT_NE(text.find("\nmissile-score 5000\n"), std::string::npos);
    EXPECT_NE(text.find("\nbonus-score 0\n"), std::string::npos);
    const replay::Replay back = replay::parse(text, "mem");
    EXPECT_EQ(back.header.missile_score, 5000);
    EXPECT_EQ(back.header.bonus_score, 0);
    // Played back in a game whose own settings are the defaults: the recorded rules win.
    Game p(default_level(), GameOptions{});
    p.start_replay(back);
    for (int i = 0; i < 60 * 60 && !p.replay_finished(); ++i) p.tick(TickCommand{});
    EXPECT_TRUE(p.replay_finished());
    EXPECT_FALSE(p.replay_mismatch().has_value());
    // A bad value is a positioned error.
    std::string bad = text;
    bad.replace(bad.find("missile-score 5000"), 18, "missile-score -4");
    EXPECT_THROW(replay::parse(bad, "mem"), std::exception);
}

TEST(ArcadeRules, TheTableTitleNamesThemAndSetRulesWaitsForTheNextGame) {
    Game g(default_level(), GameOptions{});
    const std::string plain = g.highscores_title();
    ArcadeRules r;
    r.lives = 4;
    g.set_rules(level::Difficulty::easy, r);
    EXPECT_EQ(g.highscores_title(), plain + " (4 TANKS)");
    EXPECT_EQ(g.difficulty(), level::Difficulty::easy);
    g.start_game();
    EXPECT_EQ(g.world()->lives(), 4);
}

}  // namespace
}  // namespace bz::game
