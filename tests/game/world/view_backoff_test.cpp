// Driving flush against an obstacle: the collision rule is the game's (replays depend on it)
// and stays; the view backs the eye off along the tank's heading so the obstacle shows its
// edges instead of filling the screen, never into another obstacle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "game/test_world.h"
#include "game/world/tuning.h"
#include "game/world/view_tuning.h"
#include "level/kinds.h"

namespace bz::game {
namespace {

// Distance from a ground point to an axis-aligned box footprint centred at `c`.
double to_box(glm::dvec2 p, glm::dvec2 c, double half_x, double half_z) {
    const double dx = std::max(std::abs(p.x - c.x) - half_x, 0.0);
    const double dz = std::max(std::abs(p.y - c.y) - half_z, 0.0);
    return std::hypot(dx, dz);
}

glm::dvec2 ground(const glm::dvec3& p) {
    return {p.x, p.z};
}

// Drives straight ahead (-z) until blocked; returns the frame at rest.
scene::FrameList drive_until_blocked(World& w) {
    for (int i = 0; i < 60 * 10; ++i) w.step(test::drive(1.0f, 1.0f));
    return w.interpolated_frame(1.0);
}

TEST(ViewBackoff, FlushAgainstACubeTheEyeBacksOffAndTheRuleStays) {
    const level::BuiltinKind& cube = *level::find_kind("cube");
    level::Level lv = test::empty_level();
    lv.obstacles.push_back(test::object("cube", 0.0, -20.0));
    World w = test::make_world(lv);
    const scene::FrameList f = drive_until_blocked(w);
    const glm::dvec2 tank = ground(w.state().player.body.transform.position);
    const glm::dvec2 c{0.0, -20.0};
    // The rule: the tank stopped at its collision radius from the cube (within one tick's
    // drive), exactly as before the view changed.
    const double gap = to_box(tank, c, cube.half_x, cube.half_z);
    EXPECT_GE(gap, tuning::kPlayerRadius - 1e-9);
    EXPECT_LT(gap, tuning::kPlayerRadius + tuning::kPlayerSpeed * tuning::kDt + 1e-9);
    // The view: the eye is behind the tank's centre on its heading, the cube at least the
    // clearance away, so its side and bottom edges are inside the 45 degree view.
    const glm::dvec2 eye = ground(f.camera.eye);
    EXPECT_NEAR(eye.x, tank.x, 1e-9);
    EXPECT_GT(eye.y, tank.y + 1.0);
    EXPECT_GE(to_box(eye, c, cube.half_x, cube.half_z),
              view_tuning::kEyeClearance - view_tuning::kEyeRadius - view_tuning::kEyeSearchStep);
    const double d = to_box(eye, c, cube.half_x, cube.half_z);
    const double half_h = d * std::tan(f.camera.fov_y_deg * 0.5 * 3.14159265358979 / 180.0);
    EXPECT_GT(half_h * 4.0 / 3.0, cube.half_x) << "the cube's sides are in a 4:3 view";
    EXPECT_GT(half_h, tuning::kEyeHeight) << "and its bottom edge";
    // The reticle's line is unchanged: the camera looks along the tank's heading.
    const glm::dvec3 dir = glm::normalize(f.camera.target - f.camera.eye);
    EXPECT_NEAR(dir.z, -1.0, 1e-9);
}

TEST(ViewBackoff, OpenGroundKeepsTheEyeAtTheTank) {
    World w = test::make_world(test::empty_level());
    for (int i = 0; i < 30; ++i) w.step(test::drive(1.0f, 1.0f));
    const scene::FrameList f = w.interpolated_frame(1.0);
    const glm::dvec2 tank = ground(w.state().player.body.transform.position);
    EXPECT_NEAR(glm::length(ground(f.camera.eye) - tank), 0.0, 1e-9);
}

TEST(ViewBackoff, TheEyeNeverBacksIntoAnObstacleBehind) {
    // A cube ahead stops the tank at z = -1.9; a tall box behind the start has its face at
    // z = 1.5, short of where the eye would go (z = 1.1 plus its own size): it stops short.
    level::Level lv = test::empty_level();
    lv.obstacles.push_back(test::object("cube", 0.0, -6.0));
    lv.obstacles.push_back(test::object("tall_box", 0.0, 3.0));
    World w = test::make_world(lv);
    const scene::FrameList f = drive_until_blocked(w);
    const glm::dvec2 tank = ground(w.state().player.body.transform.position);
    const glm::dvec2 eye = ground(f.camera.eye);
    const level::BuiltinKind& tall = *level::find_kind("tall_box");
    EXPECT_GT(eye.y, tank.y + 1.0) << "it still backs off as far as it can";
    EXPECT_GE(to_box(eye, {0.0, 3.0}, tall.half_x, tall.half_z), view_tuning::kEyeRadius - 1e-9);
}

}  // namespace
}  // namespace bz::game
