// The difficulty keys of [enemies] and [player]: defaults, ranges and messages.
#include <gtest/gtest.h>

#include "level/level_test_util.h"

namespace bz::level {
namespace {

using test::has_one_error;
using test::level_text;
using test::load_text;

TEST(EnemyRules, DefaultsAreTheOperatorDefaults) {
    const LoadResult r = load_text(level_text(""));
    ASSERT_TRUE(r.ok());
    const Level& l = *r.level;
    EXPECT_EQ(l.player_lives, 3);
    EXPECT_EQ(l.bonus_scores, (std::vector<int>{15000, 100000}));
    EXPECT_EQ(l.enemies.missile_score, 10000);
    EXPECT_EQ(l.enemies.slow_tank_points, 1000);
    EXPECT_EQ(l.enemies.missile_points, 2000);
    EXPECT_EQ(l.enemies.super_tank_points, 3000);
    EXPECT_EQ(l.enemies.saucer_points, 5000);
    EXPECT_EQ(l.enemies.difficulty, Difficulty::normal);
    EXPECT_FALSE(l.enemies.hold_fire);
}

TEST(EnemyRules, EveryKeyIsRead) {
    const LoadResult r = load_text(level_text(R"([player]
lives = 5
bonus_scores = [10000, 20000, 40000]
[enemies]
difficulty = "arcade"
missile_score = 3000
saucer_score = 0
super_tank_score = 7000
spawn_rear_chance = 0.0
fire_interval = 2.5
aim_error = 1.5
hold_fire = true
slow_tank_points = 100
super_tank_points = 300
missile_points = 200
saucer_points = 500
)"));
    for (const auto& e : r.errors) ADD_FAILURE() << format(e);
    ASSERT_TRUE(r.ok());
    const Level& l = *r.level;
    EXPECT_EQ(l.player_lives, 5);
    EXPECT_EQ(l.bonus_scores, (std::vector<int>{10000, 20000, 40000}));
    const EnemyRules& e = l.enemies;
    EXPECT_EQ(e.difficulty, Difficulty::arcade);
    EXPECT_EQ(e.missile_score, 3000);
    EXPECT_EQ(e.saucer_score, 0);
    EXPECT_EQ(e.super_tank_score, 7000);
    EXPECT_EQ(e.spawn_rear_chance, 0.0);
    EXPECT_EQ(e.fire_interval, 2.5);
    EXPECT_EQ(e.aim_error_deg, 1.5);
    EXPECT_TRUE(e.hold_fire);
    EXPECT_EQ(e.slow_tank_points, 100);
    EXPECT_EQ(e.super_tank_points, 300);
    EXPECT_EQ(e.missile_points, 200);
    EXPECT_EQ(e.saucer_points, 500);
}

TEST(EnemyRules, EmptyBonusListMeansNoBonusTanks) {
    const LoadResult r = load_text(level_text("[player]\nbonus_scores = []\n"));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.level->bonus_scores.empty());
}

TEST(EnemyRules, BadValuesPointAtTheValue) {
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\ndifficulty = \"hard\"\n")), 4, 14,
                              "difficulty"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nlives = 0\n")), 4, 9, "lives"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nbonus_scores = [20000, 10000]\n")), 4,
                              24, "increase"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[player]\nbonus_scores = [1.5]\n")), 4, 17,
                              "whole number"));
    EXPECT_TRUE(
        has_one_error(load_text(level_text("[player]\nbonus_scores = 15000\n")), 4, 16, "array"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\nspawn_rear_chance = 2\n")), 4, 21,
                              "spawn_rear_chance"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[enemies]\nfire_interval = 0.1\n")), 4, 17,
                              "fire_interval"));
    EXPECT_TRUE(
        has_one_error(load_text(level_text("[enemies]\nhold_fire = 1\n")), 4, 13, "hold_fire"));
}

}  // namespace
}  // namespace bz::level
