// The HUD's content lands in the expected regions (HUD units: origin at the centre, y up,
// 1 = half the screen height, x in -aspect..aspect).
#include "game/hud/hud.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "game/hud/hud_layout.h"
#include "game/test_world.h"
#include "game/world/tuning.h"
#include "support/default_font.h"

namespace bz::game {
namespace {

constexpr double kAspect = 16.0 / 9.0;

hud::View view_with_font() {
    hud::View v;
    v.aspect = kAspect;
    v.font = &bz::test::default_font();
    v.high_score = 50000;
    return v;
}

bool inside(const scene::HudLine& l, glm::vec2 lo, glm::vec2 hi) {
    auto in = [&](glm::vec2 p) { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; };
    return in(l.a) && in(l.b);
}

// Does `haystack` contain `needle` as a contiguous run of identical lines?
bool contains_run(const std::vector<scene::HudLine>& haystack,
                  const std::vector<scene::HudLine>& needle) {
    auto same = [](const scene::HudLine& x, const scene::HudLine& y) {
        return x.a == y.a && x.b == y.b && x.color == y.color;
    };
    return !needle.empty() && std::search(haystack.begin(), haystack.end(), needle.begin(),
                                          needle.end(), same) != haystack.end();
}

std::vector<scene::HudLine> text_lines(std::string_view s, glm::vec2 at, scene::TextAlign align) {
    std::vector<scene::HudLine> out;
    bz::test::default_font().draw(out, s, at, hud::kTextHeight, hud::kRed, align);
    return out;
}

TEST(Hud, RadarStaysInItsCircleAtTheTop) {
    World w = test::make_world(test::empty_level());
    w.spawn_hostile(HostileKind::slow_tank, {30, 30});
    w.step(TickCommand{});
    std::vector<scene::HudLine> out;
    hud::radar(out, w, view_with_font());
    ASSERT_GT(out.size(), 40u);
    for (const scene::HudLine& l : out) {
        EXPECT_LE(glm::length(l.a - hud::kRadarCenter), hud::kRadarRadius + 1e-4f);
        EXPECT_LE(glm::length(l.b - hud::kRadarCenter), hud::kRadarRadius + 1e-4f);
    }
    EXPECT_GT(hud::kRadarCenter.y - hud::kRadarRadius, 0.4f) << "top of the screen";
}

TEST(Hud, RadarShowsTanksButNotTheSaucer) {
    World empty = test::make_world(test::empty_level());
    std::vector<scene::HudLine> base;
    hud::radar(base, empty, view_with_font());

    World with_saucer = test::make_world(test::empty_level());
    with_saucer.spawn_saucer({0, 20});
    std::vector<scene::HudLine> saucer;
    hud::radar(saucer, with_saucer, view_with_font());
    EXPECT_EQ(saucer.size(), base.size()) << "no blip for the saucer";

    World with_tank = test::make_world(test::empty_level());
    with_tank.spawn_hostile(HostileKind::slow_tank, {-40, 40});  // ahead and to the left
    std::vector<scene::HudLine> tank;
    hud::radar(tank, with_tank, view_with_font());
    ASSERT_EQ(tank.size(), base.size() + 4) << "one diamond blip";
    const glm::vec2 blip = tank.back().a;
    EXPECT_LT(blip.x, hud::kRadarCenter.x);
    EXPECT_GT(blip.y, hud::kRadarCenter.y);
}

TEST(Hud, RadarSweepTurns) {
    World w = test::make_world(test::empty_level());
    std::vector<scene::HudLine> a, b;
    hud::radar(a, w, view_with_font());
    for (int i = 0; i < 30; ++i) w.step(TickCommand{});
    hud::radar(b, w, view_with_font());
    ASSERT_EQ(a.size(), b.size());
    // The sweep is the first line after the circle (40) and the field-of-view marks (3).
    EXPECT_NE(a[43].b, b[43].b);
    EXPECT_NEAR(glm::length(b[43].b - hud::kRadarCenter), hud::kRadarRadius, 1e-4f);
}

TEST(Hud, ReticleIsCentredAndChangesOnTarget) {
    std::vector<scene::HudLine> idle, on;
    hud::reticle(idle, false);
    hud::reticle(on, true);
    for (const auto* set : {&idle, &on}) {
        ASSERT_FALSE(set->empty());
        for (const scene::HudLine& l : *set) {
            EXPECT_TRUE(inside(l, {-hud::kReticleHalfWidth, -hud::kReticleHalfHeight},
                               {hud::kReticleHalfWidth, hud::kReticleHalfHeight}));
        }
    }
    EXPECT_FALSE(contains_run(on, idle));
    EXPECT_NE(idle.size(), on.size());
    EXPECT_GT(on[0].intensity, idle[0].intensity);

    // In play: lined up with a tank ahead gives the "on target" reticle.
    World w = test::make_world(test::empty_level());
    w.spawn_hostile(HostileKind::slow_tank, {0, 40});
    std::vector<scene::HudLine> out;
    hud::play_hud(out, w, view_with_font());
    EXPECT_TRUE(contains_run(out, on));
    w.spawn_hostile(HostileKind::slow_tank, {30, 40});
    out.clear();
    hud::play_hud(out, w, view_with_font());
    EXPECT_TRUE(contains_run(out, idle));
}

TEST(Hud, ScoreHighScoreAndTanksTopRight) {
    World w = test::make_world(test::empty_level());
    w.spawn_saucer({0, 20});
    test::fire_and_wait(w, 30);
    ASSERT_EQ(w.score(), 5000);
    std::vector<scene::HudLine> out;
    hud::play_hud(out, w, view_with_font());
    const float right = static_cast<float>(kAspect) - hud::kMargin;
    const auto score = text_lines("SCORE 5000", {right, hud::kTopLine}, scene::TextAlign::right);
    const auto high =
        text_lines("HIGH SCORE 50000", {right, hud::kSecondLine}, scene::TextAlign::right);
    EXPECT_TRUE(contains_run(out, score));
    EXPECT_TRUE(contains_run(out, high));
    for (const scene::HudLine& l : score)
        EXPECT_TRUE(inside(l, {0.3f, 0.8f}, {static_cast<float>(kAspect), 1.0f}));
    // Reserve tanks: 3 lives = the tank in play + 2 icons of 11 lines each, under the score.
    std::vector<scene::HudLine> icon;
    hud::tank_icon(icon, {0, 0}, 1.0f, hud::kRed);
    int icon_lines = 0;
    for (const scene::HudLine& l : out) {
        icon_lines += inside(l, {0.5f, hud::kLivesLine - 0.01f},
                             {static_cast<float>(kAspect), hud::kLivesLine + 0.05f});
    }
    EXPECT_EQ(icon_lines, 2 * static_cast<int>(icon.size()));
    // Nothing leaves the screen.
    for (const scene::HudLine& l : out) {
        EXPECT_TRUE(
            inside(l, {-static_cast<float>(kAspect), -1.0f}, {static_cast<float>(kAspect), 1.0f}));
    }
}

TEST(Hud, MessagesTopLeft) {
    const float left = -static_cast<float>(kAspect) + hud::kMargin;
    struct Case {
        glm::dvec2 at;
        const char* second;
    };
    for (const Case c : {Case{{-40, 5}, "ENEMY TO LEFT"}, Case{{40, 5}, "ENEMY TO RIGHT"},
                         Case{{2, -40}, "ENEMY TO REAR"}}) {
        World w = test::make_world(test::empty_level());
        for (int i = 0; i < 25; ++i) w.step(TickCommand{});  // into the "on" half of the blink
        w.spawn_hostile(HostileKind::slow_tank, c.at);
        std::vector<scene::HudLine> out;
        hud::play_hud(out, w, view_with_font());
        EXPECT_TRUE(contains_run(
            out, text_lines("ENEMY IN RANGE", {left, hud::kTopLine}, scene::TextAlign::left)));
        const auto where = text_lines(c.second, {left, hud::kSecondLine}, scene::TextAlign::left);
        EXPECT_TRUE(contains_run(out, where)) << c.second;
        for (const scene::HudLine& l : where)
            EXPECT_TRUE(inside(l, {-static_cast<float>(kAspect), 0.7f}, {0.0f, 1.0f}));
    }

    level::Level lv = test::empty_level();
    lv.obstacles.push_back(test::object("cube", 0, -6));
    World w = test::make_world(lv);
    for (int i = 0; i < 30; ++i) w.step(test::drive(1, 1));
    std::vector<scene::HudLine> out;
    hud::play_hud(out, w, view_with_font());
    EXPECT_TRUE(contains_run(out, text_lines("MOTION BLOCKED BY OBJECT", {left, hud::kSecondLine},
                                             scene::TextAlign::left)));
}

TEST(Hud, CrackedScreenWhenHit) {
    World w = test::make_world(test::empty_level());
    w.spawn_hostile(HostileKind::missile, {0, 4});
    for (int i = 0; i < 20 && w.phase() == Phase::playing; ++i) w.step(TickCommand{});
    ASSERT_EQ(w.phase(), Phase::dying);
    std::vector<scene::HudLine> early, full, again;
    hud::cracks(early, w.state().crack_seed, 0.05, kAspect);
    hud::cracks(full, w.state().crack_seed, 1.0, kAspect);
    hud::cracks(again, w.state().crack_seed, 2.0, kAspect);
    EXPECT_LT(early.size(), full.size()) << "the cracks spread";
    EXPECT_GT(full.size(), 40u);
    EXPECT_TRUE(contains_run(again, full) && again.size() == full.size()) << "then hold still";
    for (const scene::HudLine& l : full) {
        EXPECT_TRUE(inside(l, {-static_cast<float>(kAspect) - 1e-4f, -1.0001f},
                           {static_cast<float>(kAspect) + 1e-4f, 1.0001f}));
    }
    // Some crack reaches near a screen edge.
    float reach = 0.0f;
    for (const scene::HudLine& l : full)
        reach = std::max({reach, std::abs(l.b.y), std::abs(l.b.x) / static_cast<float>(kAspect)});
    EXPECT_GT(reach, 0.9f);
    // play_hud draws them while dying, and no reticle.
    std::vector<scene::HudLine> out;
    hud::View v = view_with_font();
    hud::play_hud(out, w, v);
    std::vector<scene::HudLine> ret;
    hud::reticle(ret, false);
    EXPECT_FALSE(contains_run(out, ret));
    EXPECT_GT(out.size(), 60u);
}

TEST(Hud, WorksWithoutAFont) {
    World w = test::make_world(test::empty_level());
    std::vector<scene::HudLine> out;
    hud::View v;
    hud::play_hud(out, w, v);
    EXPECT_GT(out.size(), 40u) << "radar and reticle need no text";
}

}  // namespace
}  // namespace bz::game
