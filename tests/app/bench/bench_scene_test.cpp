// The benchmark's frames are the same on every run: the camera follows the level's path at
// 1/60 s per frame, and the simulation is deterministic.
#include "app/bench/bench_scene.h"

#include <gtest/gtest.h>

#include "game/default_level.h"

namespace bz::app {
namespace {

level::Level level_with_path() {
    level::Level lv = game::default_level();
    lv.camera_path = {{0.0, {0, 5, 0}, {0, 5, -10}},
                      {2.0, {20, 5, 0}, {20, 5, -10}},
                      {4.0, {20, 25, 0}, {20, 5, -10}}};
    return lv;
}

TEST(BenchScene, CameraFollowsThePathLinearlyAndRepeats) {
    const level::Level lv = level_with_path();
    const auto at = [&](double t) { return camera_on_path(lv, t, 45.0)->eye; };
    EXPECT_EQ(at(0.0), glm::dvec3(0, 5, 0));
    EXPECT_EQ(at(1.0), glm::dvec3(10, 5, 0));
    EXPECT_EQ(at(3.0), glm::dvec3(20, 15, 0));
    EXPECT_EQ(at(5.0), at(1.0));  // a 4 s path repeats
    EXPECT_EQ(camera_on_path(lv, 1.0, 30.0)->fov_y_deg, 30.0);
    EXPECT_FALSE(camera_on_path(game::default_level(), 1.0, 45.0));
}

TEST(BenchScene, SameFramesEveryRun) {
    BenchScene a(level_with_path(), std::nullopt), b(level_with_path(), std::nullopt);
    scene::FrameList fa, fb;
    for (int i = 0; i < 90; ++i) {
        ASSERT_TRUE(a.next(fa, 16.0 / 9.0));
        ASSERT_TRUE(b.next(fb, 16.0 / 9.0));
        ASSERT_EQ(fa.items.size(), fb.items.size());
        for (std::size_t k = 0; k < fa.items.size(); ++k) {
            ASSERT_EQ(fa.items[k].mesh, fb.items[k].mesh);
            ASSERT_EQ(fa.items[k].model, fb.items[k].model);
        }
        ASSERT_EQ(fa.hud.size(), fb.hud.size());
    }
    EXPECT_DOUBLE_EQ(a.seconds(), 1.5);
    EXPECT_EQ(fa.camera.eye, camera_on_path(a.level(), 1.5, 45.0)->eye);
    EXPECT_GT(fa.items.size(), 10u);  // obstacles and the horizon
    EXPECT_FALSE(fa.hud.empty());
}

TEST(BenchScene, WithoutAPathTheAutopilotDrives) {
    BenchScene s(game::default_level(), std::nullopt);
    scene::FrameList f;
    ASSERT_TRUE(s.next(f, 1.5));
    const glm::dvec3 start = f.camera.eye;
    for (int i = 0; i < 240; ++i) s.next(f, 1.5);
    EXPECT_NE(f.camera.eye, start);
    EXPECT_NE(s.camera_description().find("autopilot"), std::string::npos);
}

}  // namespace
}  // namespace bz::app
