// Every piece of the play HUD stays in the region the layout reserves for it, the regions do
// not overlap, and the scene is kept under the band (once, text was drawn over the
// radar and the moon inside it).
#include <gtest/gtest.h>

#include "game/default_level.h"
#include "game/game.h"
#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"
#include "game/test_world.h"
#include "support/default_font.h"

namespace bz::game {
namespace {

bool in_box(const std::vector<scene::HudLine>& lines, const hud::Box& box) {
    for (const scene::HudLine& l : lines) {
        if (!box.contains(l.a) || !box.contains(l.b)) return false;
    }
    return true;
}

bool overlap(const hud::Box& a, const hud::Box& b) {
    return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

TEST(HudRegions, RegionsDoNotOverlapAtCommonAspects) {
    // The readout strip and the notices move with the text size: at either end of it.
    for (const float ts : {1.0f, 2.0f})
        for (const float aspect : {4.0f / 3.0f, 16.0f / 10.0f, 16.0f / 9.0f, 21.0f / 9.0f}) {
            const std::vector<hud::Box> boxes = {
                hud::radar_box(),        hud::messages_box(aspect),   hud::score_box(aspect),
                hud::lives_box(aspect),  hud::error_box(aspect),      hud::notice_box(aspect, ts),
                hud::footer_box(aspect), hud::readout_box(aspect, ts)};
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                EXPECT_GT(boxes[i].width(), 0.0f) << i;
                EXPECT_GT(boxes[i].height(), 0.0f) << i;
                EXPECT_GE(boxes[i].min.x, -aspect) << i;
                EXPECT_LE(boxes[i].max.x, aspect) << i;
                for (std::size_t j = i + 1; j < boxes.size(); ++j) {
                    EXPECT_FALSE(overlap(boxes[i], boxes[j]))
                        << i << " and " << j << " at " << aspect;
                }
            }
            // The band's regions are above its bottom edge; the rest below.
            for (const hud::Box& b : {hud::radar_box(), hud::messages_box(aspect),
                                      hud::score_box(aspect), hud::lives_box(aspect)}) {
                EXPECT_GE(b.min.y, hud::kBandBottom);
            }
            EXPECT_LE(hud::error_box(aspect).max.y, hud::kBandBottom);
            // The reticle sits between the error box and the notices.
            EXPECT_GT(hud::error_box(aspect).min.y, hud::kReticleHalfHeight);
            EXPECT_LT(hud::notice_box(aspect, ts).max.y, -hud::kReticleHalfHeight);
        }
}

TEST(HudRegions, EachPartDrawsOnlyInItsRegion) {
    // 800x600 to 3840x2160 and wider, at the player's smallest and largest text sizes.
    for (const float scale : {1.0f, 1.5f, 2.0f}) {
        for (const double aspect : {4.0 / 3.0, 16.0 / 9.0, 21.0 / 9.0}) {
            const auto a = static_cast<float>(aspect);
            hud::View v;
            v.text_scale = scale;
            v.aspect = aspect;
            v.font = &bz::test::default_font();
            v.high_score = 987650;
            // A world with everything showing: an enemy in range to the rear, a big score, a
            // blocked tank.
            level::Level lv = test::empty_level();
            lv.obstacles.push_back(test::object("cube", 0, -6));
            World w = test::make_world(lv);
            for (int i = 0; i < 30; ++i) w.step(test::drive(1, 1));
            w.spawn_hostile(HostileKind::slow_tank, {2, 30});
            for (int i = 0; i < 25; ++i) w.step(TickCommand{});

            std::vector<scene::HudLine> radar, status;
            hud::radar(radar, w, v);
            hud::status(status, w, v);
            ASSERT_FALSE(radar.empty());
            ASSERT_FALSE(status.empty());
            EXPECT_TRUE(in_box(radar, hud::radar_box()));
            // status = messages (left), score (right top), lives (right below): each line in one.
            int messages = 0, score = 0, lives = 0;
            for (const scene::HudLine& l : status) {
                const std::vector<scene::HudLine> one{l};
                if (in_box(one, hud::messages_box(a))) {
                    ++messages;
                } else if (in_box(one, hud::score_box(a))) {
                    ++score;
                } else if (in_box(one, hud::lives_box(a))) {
                    ++lives;
                } else {
                    ADD_FAILURE() << "a status line outside every region: (" << l.a.x << ", "
                                  << l.a.y << ") - (" << l.b.x << ", " << l.b.y << ") at aspect "
                                  << aspect;
                }
            }
            EXPECT_GT(messages, 0);
            EXPECT_GT(score, 0);
            EXPECT_GT(lives, 0);
        }
    }
}

TEST(HudRegions, LargerTextGrowsTheStatusUpToWhatItsLinesAllow) {
    hud::View v;
    EXPECT_FLOAT_EQ(hud::status_text_height(v), hud::kTextHeight);
    v.text_scale = 1.5f;
    EXPECT_FLOAT_EQ(hud::status_text_height(v), 1.5f * hud::kTextHeight);
    v.text_scale = 2.0f;
    EXPECT_GT(hud::status_text_height(v), 1.5f * hud::kTextHeight);
    EXPECT_LE(hud::status_text_height(v), hud::kTopLine - hud::kSecondLine);
}

TEST(HudRegions, TheSceneStaysUnderTheBandInPlayOnly) {
    GameOptions o;
    o.attract = true;
    Game g(default_level(), o, &bz::test::default_font());
    EXPECT_EQ(g.frame(1.0, 16.0 / 9.0).view_top, 1.0f);  // the title: the whole screen
    g.start_game();
    g.tick(TickCommand{});
    EXPECT_EQ(g.frame(1.0, 16.0 / 9.0).view_top, hud::kBandBottom);
}

TEST(HudRegions, AppMenusLeaveTitleAndPauseTextToTheApp) {
    GameOptions o;
    o.app_menus = true;
    Game g(default_level(), o, &bz::test::default_font());
    GameOptions plain;
    Game h(default_level(), plain, &bz::test::default_font());
    for (int i = 0; i < 5; ++i) {
        g.tick(TickCommand{});
        h.tick(TickCommand{});
    }
    // The same demo world under both; only the plain one adds the title text.
    EXPECT_LT(g.frame(1.0, 16.0 / 9.0).hud.size(), h.frame(1.0, 16.0 / 9.0).hud.size());
    g.start_game();
    TickCommand pause;
    pause.pause = true;
    g.tick(pause);
    ASSERT_EQ(g.screen(), Screen::paused);
    g.resume();
    EXPECT_EQ(g.screen(), Screen::playing);
    g.quit_to_title();
    EXPECT_EQ(g.screen(), Screen::attract);
}

TEST(HudRegions, HintsNameTheKeysGiven) {
    GameOptions o;
    o.hints.paused = "F9 RESUME";
    Game g(default_level(), o, &bz::test::default_font());
    g.start_game();
    TickCommand pause;
    pause.pause = true;
    g.tick(pause);
    ASSERT_EQ(g.screen(), Screen::paused);
    std::vector<scene::HudLine> want;
    bz::test::default_font().draw(want, "F9 RESUME", {0.0f, -0.5f}, 0.045f, hud::kWhite,
                                  scene::TextAlign::center);
    const auto got = g.frame(1.0, 16.0 / 9.0).hud;
    const auto it = std::search(
        got.begin(), got.end(), want.begin(), want.end(),
        [](const scene::HudLine& x, const scene::HudLine& y) { return x.a == y.a && x.b == y.b; });
    EXPECT_NE(it, got.end());
}

}  // namespace
}  // namespace bz::game
