// How things move: the missile zig-zags and hops obstacles, debris flies in parabolas, the
// saucer comes and goes on its own, the super tank is twice as fast.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "game/difficulty/autopilot.h"
#include "game/test_world.h"
#include "game/world/tuning.h"

namespace bz::game {
namespace {

TEST(WorldMotion, MissileHopsOverAnObstacleInItsPath) {
    level::Level lv = test::empty_level();
    lv.obstacles.push_back(test::object("cube", 0.0, -30.0));  // 5 high, between us
    World w = test::make_world(lv);
    w.spawn_hostile(HostileKind::missile, {0.0, 60.0});
    double highest = 0.0;
    bool passed_over = false;
    const int ticks = test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [&](const World& x) {
            if (!x.state().hostile) return true;
            const glm::dvec3 p = x.state().hostile->body.transform.position;
            highest = std::max(highest, p.y);
            if (std::abs(p.z + 30.0) < 2.5 && std::abs(p.x) < 2.5)
                passed_over = passed_over || p.y > 5.0;
            return x.phase() != Phase::playing;
        },
        60 * 20);
    EXPECT_LT(ticks, 60 * 20);
    EXPECT_GT(highest, 5.0) << "it climbed above the 5-unit cube";
    EXPECT_TRUE(passed_over) << "it crossed the cube's footprint above its top";
    EXPECT_EQ(w.phase(), Phase::dying) << "and still reached the player";
}

TEST(WorldMotion, MissileZigZagsThenRushesStraight) {
    World w = test::make_world(test::empty_level());
    w.spawn_hostile(HostileKind::missile, {0.0, 80.0});
    int sign_changes = 0;
    int last_sign = 0;
    double max_offset_far = 0.0;
    while (w.state().hostile && w.phase() == Phase::playing) {
        w.step(TickCommand{});
        if (!w.state().hostile) break;
        const glm::dvec3 p = w.state().hostile->body.transform.position;
        // The player sits at the origin facing -z: x is the sideways offset.
        const double dist = std::hypot(p.x, p.z);
        if (dist > tuning::kMissileStraightDistance + 10.0) {
            max_offset_far = std::max(max_offset_far, std::abs(p.x));
            const int s = p.x > 0.5 ? 1 : (p.x < -0.5 ? -1 : 0);
            if (s != 0 && last_sign != 0 && s != last_sign) ++sign_changes;
            if (s != 0) last_sign = s;
        }
    }
    EXPECT_GE(sign_changes, 2) << "weaves from side to side";
    EXPECT_GT(max_offset_far, 1.5);
    EXPECT_EQ(w.phase(), Phase::dying);
}

// The arcade's rule: 25,000 points after the score missiles first appear from, they turn
// nastier (tuning.h: faster and sharper-turning). Scores are reached here with the saucer (5,000)
// and a threshold of 5,000 points past a missile score of 0.
struct MissileFlight {
    std::vector<glm::dvec3> path;
    double max_offset_far = 0.0;  // sideways, while still weaving
    int ticks = 0;                // until it reached the tank
    bool nasty = false;
};

MissileFlight fly_missile(int nastier_after, bool score_first) {
    level::Level lv = test::empty_level();
    lv.enemies.missile_score = 0;
    lv.enemies.missile_nastier_after = nastier_after;
    World w = test::make_world(lv, 5);
    if (score_first) {
        w.spawn_saucer({0.0, 20.0});
        test::fire_and_wait(w, 30);
        EXPECT_EQ(w.score(), 5000);
    }
    w.spawn_hostile(HostileKind::missile, {0.0, 80.0});
    MissileFlight f;
    f.nasty = w.missile_is_nasty();
    while (w.state().hostile && w.phase() == Phase::playing && f.ticks < 2000) {
        w.step(TickCommand{});
        ++f.ticks;
        if (!w.state().hostile) break;
        const glm::dvec3 p = w.state().hostile->body.transform.position;
        f.path.push_back(p);
        if (std::hypot(p.x, p.z) > tuning::kMissileStraightDistance + 10.0) {
            f.max_offset_far = std::max(f.max_offset_far, std::abs(p.x));
        }
    }
    EXPECT_EQ(w.phase(), Phase::dying) << "the missile reached the tank";
    return f;
}

TEST(WorldMotion, MissileTurnsNastier25000PointsAfterItFirstAppears) {
    EXPECT_EQ(level::EnemyRules{}.missile_nastier_after, 25000) << "the arcade's delta";
    // Before the threshold: exactly the missile as before (the rule off, as old replays play).
    const MissileFlight before = fly_missile(5000, false);
    const MissileFlight rule_off = fly_missile(0, false);
    EXPECT_FALSE(before.nasty);
    ASSERT_EQ(before.path.size(), rule_off.path.size());
    for (std::size_t i = 0; i < before.path.size(); ++i)
        ASSERT_EQ(before.path[i], rule_off.path[i]);
    // At the same score with the rule off (an old replay): still the old missile.
    const MissileFlight old_rules = fly_missile(0, true);
    EXPECT_FALSE(old_rules.nasty);
    // Past the threshold: still weaving, it reaches the tank sooner (a quarter faster).
    const MissileFlight after = fly_missile(5000, true);
    EXPECT_TRUE(after.nasty);
    EXPECT_GT(old_rules.max_offset_far, 1.5);
    EXPECT_GT(after.max_offset_far, 1.5);
    EXPECT_LT(after.ticks, old_rules.ticks * 0.9);
    // Deterministic: the same flight twice.
    const MissileFlight again = fly_missile(5000, true);
    ASSERT_EQ(again.path.size(), after.path.size());
    for (std::size_t i = 0; i < after.path.size(); ++i) ASSERT_EQ(again.path[i], after.path[i]);
}

// Nastier means harder: the autopilot, meeting 60 missiles from all round at the same score,
// is hit by more of the nastier ones than with the rule off.
TEST(WorldMotion, NastierMissilesHitTheAutopilotMoreOften) {
    int hits[2] = {};
    for (const int i : {0, 1}) {
        for (int k = 0; k < 60; ++k) {
            level::Level lv = test::empty_level();
            lv.enemies.missile_score = 0;
            lv.enemies.missile_nastier_after = i == 0 ? 0 : 5000;
            World w = test::make_world(lv, 100 + k, 9);
            w.spawn_saucer({0.0, 20.0});
            test::fire_and_wait(w, 30);
            ASSERT_EQ(w.missile_is_nasty(), i == 1);
            const double bearing = (k * 37 % 360) * std::numbers::pi / 180.0;
            w.spawn_hostile(HostileKind::missile,
                            {80.0 * std::sin(bearing), 80.0 * std::cos(bearing)});
            const int lives = w.lives();
            for (int t = 0; t < 3000 && w.state().hostile && w.phase() == Phase::playing; ++t)
                w.step(autopilot(w));
            if (w.phase() != Phase::playing || w.lives() < lives) ++hits[i];
        }
    }
    EXPECT_GT(hits[1], hits[0] + 5) << "before " << hits[0] << ", nastier " << hits[1];
}

TEST(WorldMotion, DebrisFliesInParabolasAndSettles) {
    World w = test::make_world(test::empty_level());
    w.spawn_hostile(HostileKind::slow_tank, {0.0, 20.0});
    w.step(test::drive(0, 0, true));
    for (int i = 0; i < 60 && w.state().debris.empty(); ++i) w.step(TickCommand{});
    ASSERT_FALSE(w.state().debris.empty()) << "the tank was hit";
    const Debris first = w.state().debris.front();
    const std::uint32_t id = first.id;
    std::vector<glm::dvec3> path{first.body.transform.position};
    for (int i = 0; i < 200; ++i) {
        w.step(TickCommand{});
        for (const Debris& d : w.state().debris) {
            if (d.id == id) path.push_back(d.body.transform.position);
        }
    }
    ASSERT_GT(path.size(), 30u);
    // Up, then down, then resting on the ground.
    std::size_t top = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i].y > path[top].y) top = i;
    }
    EXPECT_GT(top, 0u);
    EXPECT_GT(path[top].y, first.body.transform.position.y + 1.0);
    EXPECT_EQ(path.back().y, 0.0);
    // Before landing the horizontal speed is constant and the vertical one falls by g each tick.
    const glm::dvec3 v0 = (path[2] - path[1]) * 60.0;
    const glm::dvec3 v1 = (path[3] - path[2]) * 60.0;
    EXPECT_NEAR(v0.x, v1.x, 1e-6);
    EXPECT_NEAR(v0.z, v1.z, 1e-6);
    EXPECT_NEAR(v0.y - v1.y, tuning::kGravity / 60.0, 1e-6);
    // Eventually it is gone.
    for (int i = 0; i < tuning::kDebrisTicks; ++i) w.step(TickCommand{});
    EXPECT_TRUE(w.state().debris.empty());
}

TEST(WorldMotion, SaucerComesAndGoesOnItsOwn) {
    level::Level lv = test::empty_level();
    lv.enemies.saucer = true;
    lv.enemies.saucer_score = 0;
    World w = test::make_world(lv, 4);
    const int arrive = test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [](const World& x) { return x.state().saucer.has_value(); },
        tuning::kSaucerMaxDelayTicks + 10);
    EXPECT_GE(arrive, tuning::kSaucerMinDelayTicks - 1);
    EXPECT_LE(arrive, tuning::kSaucerMaxDelayTicks);
    ASSERT_TRUE(w.state().saucer.has_value());
    EXPECT_TRUE(w.radar_blips().empty());
    const int stay = test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [](const World& x) { return !x.state().saucer.has_value(); },
        tuning::kSaucerLifeTicks + 10);
    EXPECT_EQ(stay, tuning::kSaucerLifeTicks);
    EXPECT_EQ(w.phase(), Phase::playing) << "harmless";
}

TEST(WorldMotion, SaucerWaitsForItsScore) {
    level::Level lv = test::empty_level();
    lv.enemies.saucer = true;
    lv.enemies.saucer_score = 1000;
    World w = test::make_world(lv, 4);
    const int wait = tuning::kSaucerMaxDelayTicks + 120;
    EXPECT_EQ(test::run_until(
                  w, [](const World&) { return TickCommand{}; },
                  [](const World& x) { return x.state().saucer.has_value(); }, wait),
              wait)
        << "no saucer below its score";
    // Score a tank: the saucer, long overdue, comes at once.
    w.spawn_hostile(HostileKind::slow_tank, {0.0, 20.0});
    test::fire_and_wait(w, 60);
    ASSERT_GE(w.score(), 1000);
    const int arrive = test::run_until(
        w, [](const World&) { return TickCommand{}; },
        [](const World& x) { return x.state().saucer.has_value(); }, 10);
    EXPECT_LT(arrive, 10);
}

TEST(WorldMotion, SuperTankIsTwiceAsFast) {
    double moved[2] = {0.0, 0.0};
    int k = 0;
    for (HostileKind kind : {HostileKind::slow_tank, HostileKind::super_tank}) {
        World w = test::make_world(test::empty_level());
        w.spawn_hostile(kind, {0.0, 150.0});  // far: it drives straight in
        const glm::dvec3 a = w.state().hostile->body.transform.position;
        for (int i = 0; i < 60; ++i) w.step(TickCommand{});
        moved[k++] = glm::length(w.state().hostile->body.transform.position - a);
    }
    EXPECT_NEAR(moved[1] / moved[0], 2.0, 0.1);
    EXPECT_NEAR(moved[0], tuning::kTankSpeed, 0.3);
}

}  // namespace
}  // namespace bz::game
