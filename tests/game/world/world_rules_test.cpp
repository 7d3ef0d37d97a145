// Battlezone rules driven by scripted commands: shooting, obstacles, enemy kinds, the saucer,
// bonus tanks and game over.
#include <gtest/gtest.h>

#include <cmath>

#include "game/difficulty/autopilot.h"
#include "game/test_world.h"
#include "game/world/tuning.h"

namespace bz::game {
namespace {

using test::drive;
using test::empty_level;
using test::fire_and_wait;
using test::has;
using test::make_world;
using test::object;

TEST(WorldRules, ShellHitsTankScoresAndDestroysIt) {
    World w = make_world(empty_level());
    w.spawn_hostile(HostileKind::slow_tank, {0.0, 30.0});
    ASSERT_TRUE(w.state().hostile.has_value());
    std::vector<SoundEvent> events;
    fire_and_wait(w, 60, &events);
    EXPECT_EQ(w.score(), 1000);
    EXPECT_FALSE(w.state().hostile.has_value());
    EXPECT_EQ(w.state().kills, 1);
    EXPECT_TRUE(has(events, SoundEvent::shot));
    EXPECT_TRUE(has(events, SoundEvent::explosion));
    EXPECT_FALSE(w.state().debris.empty()) << "a destroyed tank leaves debris";
}

TEST(WorldRules, SuperTankMissileAndSaucerScores) {
    struct Case {
        HostileKind kind;
        int points;
    };
    for (const Case c : {Case{HostileKind::super_tank, 3000}, Case{HostileKind::missile, 2000}}) {
        World w = make_world(empty_level());
        w.spawn_hostile(c.kind, {0.0, 25.0});
        fire_and_wait(w, 40);
        EXPECT_EQ(w.score(), c.points) << static_cast<int>(c.kind);
    }
    World w = make_world(empty_level());
    w.spawn_saucer({0.0, 25.0});
    fire_and_wait(w, 40);
    EXPECT_EQ(w.score(), 5000);
    EXPECT_FALSE(w.state().saucer.has_value());
}

TEST(WorldRules, OnlyOnePlayerShellInFlight) {
    World w = make_world(empty_level());
    int shots = 0;
    for (int i = 0; i < 40; ++i) {
        w.step(drive(0, 0, i % 2 == 0));  // hammer the button
        for (SoundEvent e : w.events()) shots += e == SoundEvent::shot;
        int in_flight = 0;
        for (const Shell& s : w.state().shells) in_flight += s.from_player;
        ASSERT_LE(in_flight, 1);
    }
    // The shell lives kShellRange / kShellSpeed = 2.4 s, so 40 ticks allow exactly one shot.
    EXPECT_EQ(shots, 1);
}

TEST(WorldRules, ObstacleBlocksMotionWithMessage) {
    level::Level lv = empty_level();
    lv.obstacles.push_back(object("cube", 0.0, -12.0));  // straight ahead (yaw 0 faces -z)
    World w = make_world(lv);
    std::vector<SoundEvent> events;
    for (int i = 0; i < 300; ++i) {
        w.step(drive(1, 1));
        events.insert(events.end(), w.events().begin(), w.events().end());
    }
    const double z = w.state().player.body.transform.position.z;
    // The cube's near face is at z = -9.5; the tank (radius 1.6) stops short of it.
    EXPECT_GT(z, -9.5 + tuning::kPlayerRadius - 0.2);
    EXPECT_LT(z, -9.5 + tuning::kPlayerRadius + 0.5) << "it drove up to the cube first";
    EXPECT_TRUE(w.awareness().motion_blocked);
    EXPECT_TRUE(has(events, SoundEvent::blocked));

    // The same drive without the cube covers 300 ticks * 7 u/s / 60 = 35 units.
    World open = make_world(empty_level());
    for (int i = 0; i < 300; ++i) open.step(drive(1, 1));
    EXPECT_NEAR(open.state().player.body.transform.position.z, -35.0, 0.01);
    EXPECT_FALSE(open.awareness().motion_blocked);

    // Turning away frees it and the message clears.
    for (int i = 0; i < 300; ++i) w.step(drive(-1, 1));
    for (int i = 0; i < 60; ++i) w.step(drive(1, 1));
    EXPECT_FALSE(w.awareness().motion_blocked);
}

TEST(WorldRules, ObstacleStopsShells) {
    level::Level lv = empty_level();
    lv.obstacles.push_back(object("tall_box", 0.0, -20.0));
    World w = make_world(lv);
    w.spawn_hostile(HostileKind::slow_tank, {0.0, 40.0});  // hidden behind the pillar
    std::vector<SoundEvent> events;
    fire_and_wait(w, 50, &events);
    EXPECT_TRUE(has(events, SoundEvent::shell_impact));
    EXPECT_EQ(w.score(), 0);
    EXPECT_TRUE(w.state().hostile.has_value());
    for (const Shell& s : w.state().shells) EXPECT_FALSE(s.from_player);
}

TEST(WorldRules, MissileOnlyPastItsScoreThreshold) {
    level::Level lv = empty_level();
    lv.enemies.missile = true;
    lv.enemies.missile_score = 5000;
    World w = make_world(lv, 7);
    for (int i = 0; i < 1200; ++i) {
        w.step(TickCommand{});
        ASSERT_FALSE(w.state().hostile.has_value()) << "tick " << i << " at score " << w.score();
    }
    // Shooting the saucer takes the score to the threshold; a missile follows.
    w.spawn_saucer({0.0, 20.0});
    fire_and_wait(w, 30);
    ASSERT_EQ(w.score(), 5000);
    const int waited = test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [](const World& x) { return x.state().hostile.has_value(); }, 600);
    ASSERT_LT(waited, 600);
    EXPECT_EQ(w.state().hostile->kind, HostileKind::missile);
}

TEST(WorldRules, MixedEnemiesNeverMissileBelowThreshold) {
    // Slow tanks and missiles allowed; the autopilot plays until it passes the threshold.
    level::Level lv = empty_level();
    lv.enemies.slow_tank = true;
    lv.enemies.missile = true;
    lv.enemies.missile_score = 4000;
    World w = make_world(lv, 11, 9);
    std::uint32_t last_id = 0;
    int missiles_before = 0;
    int missiles_after = 0;
    for (int i = 0; i < 60 * 60 * 4 && !w.game_over(); ++i) {
        const int score_before = w.score();
        w.step(autopilot(w));
        const auto& h = w.state().hostile;
        if (h && h->id != last_id) {
            last_id = h->id;
            if (h->kind == HostileKind::missile) {
                (score_before < 4000 ? missiles_before : missiles_after)++;
            }
        }
    }
    EXPECT_EQ(missiles_before, 0);
    EXPECT_GE(w.score(), 4000) << "the autopilot should pass the threshold in four minutes";
    EXPECT_GT(missiles_after, 0);
}

TEST(WorldRules, SaucerIsNotOnRadarButTanksAre) {
    World w = make_world(empty_level());
    w.spawn_saucer({10.0, 30.0});
    w.step(TickCommand{});
    EXPECT_TRUE(w.state().saucer.has_value());
    EXPECT_TRUE(w.radar_blips().empty());
    EXPECT_FALSE(w.awareness().enemy_present);

    w.spawn_hostile(HostileKind::slow_tank, {-20.0, 30.0});
    w.step(TickCommand{});
    ASSERT_EQ(w.radar_blips().size(), 1u);
    EXPECT_LT(w.radar_blips()[0].offset.x, 0.0) << "to the left";
    EXPECT_GT(w.radar_blips()[0].offset.y, 0.0) << "ahead";
    EXPECT_TRUE(w.state().saucer.has_value()) << "the saucer may share the field with a hostile";
}

TEST(WorldRules, BonusTankAt15000) {
    World w = make_world(empty_level());
    ASSERT_EQ(w.lives(), 3);
    std::vector<SoundEvent> events;
    for (int k = 0; k < 3; ++k) {
        w.spawn_saucer({0.0, 20.0});
        fire_and_wait(w, 40, &events);
        if (k < 2) {
            EXPECT_EQ(w.lives(), 3) << "no bonus at " << w.score();
            EXPECT_FALSE(has(events, SoundEvent::bonus_life));
        }
    }
    EXPECT_EQ(w.score(), 15000);
    EXPECT_EQ(w.lives(), 4);
    EXPECT_TRUE(has(events, SoundEvent::bonus_life));
}

TEST(WorldRules, SecondBonusAt100000AndNoMore) {
    World w = make_world(empty_level());
    int bonuses = 0;
    for (int k = 0; k < 21; ++k) {  // 21 saucers: 105,000 points
        w.spawn_saucer({0.0, 20.0});
        std::vector<SoundEvent> events;
        fire_and_wait(w, 40, &events);
        for (SoundEvent e : events) bonuses += e == SoundEvent::bonus_life;
        if (w.score() == 95000) {
            EXPECT_EQ(w.lives(), 4);
        }
    }
    EXPECT_EQ(w.score(), 105000);
    EXPECT_EQ(bonuses, 2);
    EXPECT_EQ(w.lives(), 5);
}

TEST(WorldRules, SuperTankOnlyFromItsThresholdAndSpawnsAtLevelDistances) {
    level::Level lv = empty_level();
    lv.enemies.super_tank = true;
    lv.enemies.super_tank_score = 5000;
    lv.enemies.spawn_min_distance = 50.0;
    lv.enemies.spawn_max_distance = 60.0;
    World w = make_world(lv, 3);
    for (int i = 0; i < 900; ++i) {
        w.step(TickCommand{});
        ASSERT_FALSE(w.state().hostile.has_value());
    }
    w.spawn_saucer({0.0, 20.0});
    fire_and_wait(w, 30);
    ASSERT_EQ(w.score(), 5000);
    test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [](const World& x) { return x.state().hostile.has_value(); }, 600);
    ASSERT_TRUE(w.state().hostile.has_value());
    EXPECT_EQ(w.state().hostile->kind, HostileKind::super_tank);
    const double d = w.field().distance(ground(w.state().player.body.transform.position),
                                        ground(w.state().hostile->body.transform.position));
    EXPECT_GE(d, 50.0 - 0.2);  // it may have moved a tick's worth
    EXPECT_LE(d, 60.0 + 0.2);
}

TEST(WorldRules, LivesRunOutIntoGameOver) {
    World w = make_world(empty_level());
    for (int life = 3; life >= 1; --life) {
        ASSERT_EQ(w.phase(), Phase::playing);
        ASSERT_EQ(w.lives(), life);
        // A missile right in front: it reaches the tank within a few ticks.
        w.spawn_hostile(HostileKind::missile, {0.0, 4.0});
        std::vector<SoundEvent> events;
        for (int i = 0; i < 30 && w.phase() == Phase::playing; ++i) {
            w.step(TickCommand{});
            events.insert(events.end(), w.events().begin(), w.events().end());
        }
        ASSERT_EQ(w.phase(), Phase::dying);
        EXPECT_TRUE(has(events, SoundEvent::player_death));
        EXPECT_EQ(w.lives(), life - 1);
        for (int i = 0; i < tuning::kDyingTicks + 1; ++i) w.step(TickCommand{});
    }
    EXPECT_TRUE(w.game_over());
    const std::uint64_t frozen = w.state().score;
    for (int i = 0; i < 100; ++i) w.step(drive(1, 1, true));
    EXPECT_TRUE(w.game_over());
    EXPECT_EQ(static_cast<std::uint64_t>(w.state().score), frozen);
}

TEST(WorldRules, EnemyShellKillsThePlayer) {
    level::Level lv = empty_level();
    lv.enemies.aggression = 1.0;
    World w = make_world(lv);
    w.spawn_hostile(HostileKind::slow_tank, {0.0, 30.0});
    bool fired = false;
    const int ticks = test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [](const World& x) { return x.phase() != Phase::playing; }, 60 * 20,
        [&](SoundEvent e) { fired |= e == SoundEvent::enemy_shot; });
    EXPECT_LT(ticks, 60 * 20) << "a tank facing a sitting target should hit it";
    EXPECT_TRUE(fired);
    EXPECT_EQ(w.lives(), 2);
}

TEST(WorldRules, EnemyTankHuntsFromAfar) {
    level::Level lv = empty_level();
    World w = make_world(lv);
    w.spawn_hostile(HostileKind::slow_tank, {60.0, 80.0}, 70.0);  // facing well away
    const double start =
        glm::length(w.field().delta(ground(w.state().player.body.transform.position),
                                    ground(w.state().hostile->body.transform.position)));
    for (int i = 0; i < 60 * 10; ++i) w.step(TickCommand{});
    ASSERT_TRUE(w.state().hostile.has_value());
    const double now =
        glm::length(w.field().delta(ground(w.state().player.body.transform.position),
                                    ground(w.state().hostile->body.transform.position)));
    EXPECT_LT(now, start - 20.0) << "it closes in";
}

TEST(WorldRules, EnemiesNeverSpawnInsideObstacles) {
    // A crowded field: many spawn attempts land on obstacles and must be rejected.
    level::Level lv = empty_level();
    lv.enemies.slow_tank = true;
    for (int x = -180; x <= 180; x += 12) {
        for (int z = -180; z <= 180; z += 12) {
            if (std::hypot(x, z) > 12.0) lv.obstacles.push_back(object("cube", x, z));
        }
    }
    int spawned = 0;
    for (std::uint64_t seed = 1; seed <= 25; ++seed) {
        World w = make_world(lv, seed);
        test::run_until(
            w, [](const World&) { return TickCommand{}; },
            [](const World& x) { return x.state().hostile.has_value(); }, 400);
        if (!w.state().hostile) continue;
        ++spawned;
        const glm::dvec2 p = ground(w.state().hostile->body.transform.position);
        for (const scene::Entity& o : w.obstacles()) {
            const glm::dvec2 d = w.field().delta(ground(o.transform.position), p);
            // Cube half width 2.5: the tank's circle must clear the square.
            const glm::dvec2 q = glm::max(glm::abs(d) - glm::dvec2(2.5), glm::dvec2(0.0));
            EXPECT_GT(glm::length(q), tuning::kTankRadius) << "seed " << seed;
        }
    }
    EXPECT_GT(spawned, 20);
}

TEST(WorldRules, FieldWrapsAround) {
    level::Level lv = empty_level();
    lv.field_size = 100.0;
    World w = make_world(lv);
    for (int i = 0; i < 60 * 10; ++i) w.step(drive(1, 1));  // 70 units towards -z
    const double z = w.state().player.body.transform.position.z;
    EXPECT_NEAR(z, 30.0, 0.01) << "-70 wraps to +30 on a 100-unit field";

    lv.wrap = false;
    World closed = make_world(lv);
    for (int i = 0; i < 60 * 10; ++i) closed.step(drive(1, 1));
    EXPECT_NEAR(closed.state().player.body.transform.position.z, -50.0 + tuning::kPlayerRadius,
                0.2);
    EXPECT_TRUE(closed.awareness().motion_blocked);
}

TEST(WorldRules, DirectionMessages) {
    World w = make_world(empty_level());
    struct Case {
        glm::dvec2 at;
        EnemyDirection dir;
    };
    for (const Case c :
         {Case{{0, 40}, EnemyDirection::ahead}, Case{{-40, 5}, EnemyDirection::left},
          Case{{40, 5}, EnemyDirection::right}, Case{{3, -40}, EnemyDirection::rear}}) {
        w.spawn_hostile(HostileKind::slow_tank, c.at);
        const Awareness a = w.awareness();
        EXPECT_TRUE(a.enemy_present);
        EXPECT_TRUE(a.enemy_in_range);
        EXPECT_EQ(a.direction, c.dir) << c.at.x << "," << c.at.y;
        EXPECT_EQ(a.in_sights, c.dir == EnemyDirection::ahead);
    }
}

}  // namespace
}  // namespace bz::game
