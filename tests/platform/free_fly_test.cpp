#include "platform/free_fly.h"

#include <gtest/gtest.h>

namespace bz::platform {
namespace {

void expect_near(glm::dvec3 a, glm::dvec3 b) {
    EXPECT_NEAR(a.x, b.x, 1e-9);
    EXPECT_NEAR(a.y, b.y, 1e-9);
    EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(FreeFly, HeadingConvention) {
    expect_near(FreeFlyCamera({0, 0, 0}, 0.0).forward(), {0, 0, -1});
    expect_near(FreeFlyCamera({0, 0, 0}, 90.0).forward(), {-1, 0, 0});
    expect_near(FreeFlyCamera({0, 0, 0}, 0.0, 30.0).forward(), {0, 0.5, -std::sqrt(0.75)});
}

TEST(FreeFly, MovesAlongTheGroundAtItsSpeed) {
    FreeFlyCamera cam({1, 2, 3}, 90.0, 45.0);
    FlyControls c;
    c.forward = 1.0f;
    cam.update(c, 0.5);
    expect_near(cam.position(), {1 - 0.5 * FreeFlyCamera::kSpeed, 2, 3});  // pitch ignored
    c = {};
    c.right = 1.0f;
    c.up = 1.0f;
    c.fast = true;
    cam.update(c, 0.1);
    const double d = 0.1 * FreeFlyCamera::kSpeed * FreeFlyCamera::kFastFactor;
    expect_near(cam.position(), {1 - 0.5 * FreeFlyCamera::kSpeed, 2 + d, 3 - d});
}

TEST(FreeFly, LookClampsPitchAndIgnoresBadTime) {
    FreeFlyCamera cam({0, 0, 0}, 0.0);
    FlyControls c;
    c.mouse_dy = -100000.0f;  // mouse far up
    cam.update(c, 0.016);
    EXPECT_DOUBLE_EQ(cam.pitch_deg(), FreeFlyCamera::kMaxPitch);
    c = {};
    c.yaw = 1.0f;
    cam.update(c, 1.0);
    EXPECT_NEAR(cam.yaw_deg(), FreeFlyCamera::kTurnRate, 1e-9);
    const glm::dvec3 before = cam.position();
    c.forward = 1.0f;
    cam.update(c, -1.0);
    cam.update(c, std::nan(""));
    expect_near(cam.position(), before);
}

}  // namespace
}  // namespace bz::platform
