// Difficulty as data: the three settings scale the level's rules as documented, and the shipped
// levels meet the goals on the deterministic simulation (20 seeds each):
//   - the tutorial never kills an idle player in 120 s;
//   - classic on normal gives an idle player at least 20 s before the first death on average;
//   - enemies appear inside the rear 90 degrees at most a quarter of the time;
//   - the saucer and a bonus tank appear in autopilot games that reach their scores.
#include "game/difficulty/difficulty.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "game/difficulty/difficulty_probe.h"
#include "game/records/replay.h"
#include "level/loader.h"
#include "support/tree_paths.h"

namespace bz::game {
namespace {

constexpr int kSeeds = 20;

level::Level shipped(const std::string& name) {
    const level::LoadResult r = level::load_level_file(bz::test::source_dir() / "levels" / name);
    for (const auto& e : r.errors) ADD_FAILURE() << level::format(e);
    return r.level.value_or(level::Level{});
}

TEST(Difficulty, NamesRoundTrip) {
    for (const Difficulty d : {Difficulty::easy, Difficulty::normal, Difficulty::arcade}) {
        EXPECT_EQ(parse_difficulty(difficulty_name(d)), d);
    }
    EXPECT_FALSE(parse_difficulty("hard").has_value());
    EXPECT_FALSE(parse_difficulty("").has_value());
}

TEST(Difficulty, NormalIsTheLevelAsWritten) {
    level::EnemyRules r;
    r.aggression = 0.37;
    r.fire_interval = 3.3;
    r.aim_error_deg = 2.2;
    r.spawn_min_distance = 41.0;
    r.spawn_max_distance = 77.0;
    r.spawn_rear_chance = 0.05;
    const level::EnemyRules n = rules_for(r, 400.0, Difficulty::normal);
    EXPECT_DOUBLE_EQ(n.aggression, r.aggression);
    EXPECT_DOUBLE_EQ(n.fire_interval, r.fire_interval);
    EXPECT_DOUBLE_EQ(n.aim_error_deg, r.aim_error_deg);
    EXPECT_DOUBLE_EQ(n.spawn_min_distance, r.spawn_min_distance);
    EXPECT_DOUBLE_EQ(n.spawn_max_distance, r.spawn_max_distance);
    EXPECT_DOUBLE_EQ(n.spawn_rear_chance, r.spawn_rear_chance);
    EXPECT_EQ(n.difficulty, Difficulty::normal);
}

TEST(Difficulty, EasyIsCalmerAndArcadeHarsherButScoringStays) {
    const level::EnemyRules r;  // the defaults
    const level::EnemyRules easy = rules_for(r, 400.0, Difficulty::easy);
    const level::EnemyRules arcade = rules_for(r, 400.0, Difficulty::arcade);
    EXPECT_LT(easy.aggression, r.aggression);
    EXPECT_GT(arcade.aggression, r.aggression);
    EXPECT_GT(easy.fire_interval, r.fire_interval);
    EXPECT_LT(arcade.fire_interval, r.fire_interval);
    EXPECT_GT(easy.aim_error_deg, r.aim_error_deg);
    EXPECT_LT(arcade.aim_error_deg, r.aim_error_deg);
    EXPECT_GT(easy.spawn_min_distance, r.spawn_min_distance);
    EXPECT_LT(easy.spawn_rear_chance, r.spawn_rear_chance);
    EXPECT_GT(arcade.spawn_rear_chance, r.spawn_rear_chance);
    EXPECT_LE(arcade.spawn_rear_chance, 0.25);
    for (const level::EnemyRules* x : {&easy, &arcade}) {
        EXPECT_EQ(x->missile_score, 10000);
        EXPECT_EQ(x->saucer_score, r.saucer_score);
        EXPECT_EQ(x->slow_tank_points, 1000);
        EXPECT_EQ(x->missile_points, 2000);
        EXPECT_EQ(x->super_tank_points, 3000);
        EXPECT_EQ(x->saucer_points, 5000);
        EXPECT_EQ(x->hold_fire, r.hold_fire);
    }
    // A passive level stays passive, and spawn rings stay on a small field.
    level::EnemyRules calm;
    calm.aggression = 0.0;
    EXPECT_EQ(rules_for(calm, 400.0, Difficulty::arcade).aggression, 0.0);
    const level::EnemyRules small = rules_for(r, 100.0, Difficulty::easy);
    EXPECT_LE(small.spawn_max_distance, 50.0);
    EXPECT_LE(small.spawn_min_distance, small.spawn_max_distance);
}

TEST(Difficulty, OperatorDefaults) {
    const level::Level lv;
    EXPECT_EQ(lv.player_lives, 3);
    ASSERT_EQ(lv.bonus_scores.size(), 2u);
    EXPECT_EQ(lv.bonus_scores[0], 15000);
    EXPECT_EQ(lv.bonus_scores[1], 100000);
    EXPECT_EQ(lv.enemies.missile_score, 10000);
    EXPECT_EQ(lv.enemies.difficulty, Difficulty::normal);
}

TEST(Difficulty, ReplayHeaderKeepsTheDifficulty) {
    replay::Replay r;
    r.header.seed = 5;
    r.header.level = "x.toml";
    r.header.difficulty = Difficulty::arcade;
    const replay::Replay back = replay::parse(replay::serialise(r), "test");
    EXPECT_EQ(back.header.difficulty, Difficulty::arcade);
    // Files from before the setting existed play at normal.
    std::string old = replay::serialise(r);
    old.erase(old.find("difficulty arcade\n"), 18);
    EXPECT_EQ(replay::parse(old, "old").header.difficulty, Difficulty::normal);
    std::string bad = replay::serialise(r);
    bad.replace(bad.find("arcade"), 6, "brutal");
    EXPECT_THROW(replay::parse(bad, "bad"), std::exception);
}

TEST(DifficultyGoals, TutorialNeverKillsAnIdlePlayerIn120Seconds) {
    const level::Level lv = shipped("tutorial.toml");
    const Assets assets(lv.backdrop);
    for (const Difficulty d : {Difficulty::easy, Difficulty::normal, Difficulty::arcade}) {
        const ProbeSummary s = probe_summary(lv, assets, d, Pilot::idle, kSeeds);
        EXPECT_EQ(s.survived, kSeeds)
            << difficulty_name(d) << ": first death after " << s.min_first_death_s << " s";
        EXPECT_GT(s.spawns, 0) << "the tutorial must still send tanks";
    }
}

TEST(DifficultyGoals, ClassicNormalGivesAnIdlePlayerTwentySeconds) {
    const level::Level lv = shipped("classic.toml");
    const Assets assets(lv.backdrop);
    const ProbeSummary s = probe_summary(lv, assets, Difficulty::normal, Pilot::idle, kSeeds);
    EXPECT_GE(s.mean_first_death_s, 20.0);
    EXPECT_LT(s.survived, kSeeds) << "an idle player should still be in danger";
    // Easy is kinder than normal, arcade harsher.
    const ProbeSummary easy = probe_summary(lv, assets, Difficulty::easy, Pilot::idle, kSeeds);
    const ProbeSummary arcade = probe_summary(lv, assets, Difficulty::arcade, Pilot::idle, kSeeds);
    EXPECT_GT(easy.mean_first_death_s, s.mean_first_death_s);
    EXPECT_LT(arcade.mean_first_death_s, s.mean_first_death_s);
}

TEST(DifficultyGoals, EnemiesRarelyAppearBehindThePlayer) {
    for (const char* name : {"classic.toml", "maze.toml", "volcano_night.toml", "plains.toml"}) {
        const level::Level lv = shipped(name);
        const Assets assets(lv.backdrop);
        ProbeOptions o;
        o.stop_at_first_death = false;  // every spawn of a whole game
        int spawns = 0, rear = 0;
        for (const Pilot p : {Pilot::idle, Pilot::autopilot}) {
            const ProbeSummary s = probe_summary(lv, assets, Difficulty::normal, p, kSeeds, 1, o);
            spawns += s.spawns;
            rear += s.rear_spawns;
        }
        ASSERT_GE(spawns, 40) << name;
        EXPECT_LE(rear * 4, spawns) << name << ": " << rear << " of " << spawns << " behind";
    }
}

TEST(DifficultyGoals, SaucerAndBonusTankAppearWhenTheAutopilotReachesTheirScores) {
    const level::Level lv = shipped("classic.toml");
    const Assets assets(lv.backdrop);
    ProbeOptions o;
    o.stop_at_first_death = false;
    o.max_seconds = 600.0;
    int reached_saucer = 0, saw_saucer = 0, reached_bonus = 0;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        const ProbeRun r = probe_game(lv, assets, Difficulty::normal,
                                      static_cast<std::uint64_t>(seed), Pilot::autopilot, o);
        if (r.saucer_seen_s) {
            ASSERT_TRUE(r.saucer_score_s) << "seed " << seed << ": a saucer before its score";
            EXPECT_GE(*r.saucer_seen_s, *r.saucer_score_s) << "seed " << seed;
        }
        if (r.saucer_score_s) {
            ++reached_saucer;
            if (r.saucer_seen_s) ++saw_saucer;
        }
        if (r.bonus_score_s) {
            ++reached_bonus;
            ASSERT_TRUE(r.bonus_awarded_s) << "seed " << seed;
            EXPECT_EQ(*r.bonus_awarded_s, *r.bonus_score_s) << "seed " << seed;
        } else {
            EXPECT_FALSE(r.bonus_awarded_s) << "seed " << seed;
        }
    }
    std::printf(
        "autopilot on classic, normal: %d of %d games reached the saucer's score, %d saw "
        "it; %d reached the first bonus score\n",
        reached_saucer, kSeeds, saw_saucer, reached_bonus);
    ASSERT_GT(reached_saucer, kSeeds / 2) << "the autopilot should reach the saucer's score";
    EXPECT_EQ(saw_saucer, reached_saucer);
    ASSERT_GT(reached_bonus, 0) << "no autopilot game reached the first bonus score";
}

}  // namespace
}  // namespace bz::game
