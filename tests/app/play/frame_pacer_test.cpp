#include "app/play/frame_pacer.h"

#include <gtest/gtest.h>

namespace bz::app {
namespace {

TEST(FramePacer, WithoutVsyncPlayIsCappedAtTheDisplayRate) {
    PaceInput in;
    in.display_hz = 75;
    EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / 75);
    in.display_hz = 0;  // unknown: 60
    EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / 60);
    in.vsync_in_effect = true;  // vsync paces the game itself
    EXPECT_EQ(min_frame_seconds(in), 0.0);
    in.max_fps = 144;  // the player's cap applies either way
    EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / 144);
}

TEST(FramePacer, MenusPauseAndHiddenWindowsDrawAtALowRate) {
    for (const bool vsync : {false, true}) {
        PaceInput in;
        in.vsync_in_effect = vsync;
        in.scene = PaceScene::title_menu;
        EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / kTitleMenuFps);
        in.scene = PaceScene::paused;
        EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / kPausedFps);
        in.scene = PaceScene::hidden;
        EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / kHiddenFps);
        in.max_fps = 20;  // a lower cap of the player's still wins in menus
        in.scene = PaceScene::title_menu;
        EXPECT_DOUBLE_EQ(min_frame_seconds(in), 1.0 / 20);
    }
}

TEST(FramePacer, TestRunsAreNeverPaced) {
    PaceInput in;
    in.test_run = true;
    for (const PaceScene s :
         {PaceScene::play, PaceScene::title_menu, PaceScene::paused, PaceScene::hidden}) {
        in.scene = s;
        EXPECT_EQ(min_frame_seconds(in), 0.0);
    }
}

}  // namespace
}  // namespace bz::app
