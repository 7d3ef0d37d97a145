#include <gtest/gtest.h>

#include <cmath>

#include "game/fixed_step.h"
#include "game/test_world.h"
#include "game/world/tick_command.h"

namespace bz::game {
namespace {

TEST(FixedStep, SixtyHzFramesGiveOneTickEach) {
    FixedStep fs;
    int ticks = 0;
    for (int i = 0; i < 600; ++i) ticks += fs.advance(1.0 / 60.0).ticks;
    EXPECT_EQ(ticks, 600);
}

TEST(FixedStep, SlowFramesRunSeveralTicksAndCarryTheRemainder) {
    FixedStep fs;
    StepPlan p = fs.advance(0.05);  // 3 ticks of 1/60
    EXPECT_EQ(p.ticks, 3);
    EXPECT_NEAR(p.alpha, 0.0, 1e-6);
    p = fs.advance(0.01);  // 0.6 of a tick
    EXPECT_EQ(p.ticks, 0);
    EXPECT_NEAR(p.alpha, 0.6, 1e-6);
    p = fs.advance(0.01);
    EXPECT_EQ(p.ticks, 1);
    EXPECT_NEAR(p.alpha, 0.2, 1e-6);
}

TEST(FixedStep, LongFramesAreCappedAndCatchUpIsLimited) {
    FixedStep fs(0.25, 5);
    StepPlan p = fs.advance(10.0);  // a debugger stop
    EXPECT_EQ(p.ticks, 5);
    EXPECT_GE(p.alpha, 0.0);
    EXPECT_LE(p.alpha, 1.0);
    // The backlog was dropped, not queued: the next normal frame runs one tick.
    p = fs.advance(1.0 / 60.0);
    EXPECT_LE(p.ticks, 2);
    p = fs.advance(std::nan(""));
    EXPECT_EQ(p.ticks, 0);
    p = fs.advance(-1.0);
    EXPECT_EQ(p.ticks, 0);
}

TEST(TickCommand, PackRoundTripsAndClamps) {
    TickCommand c;
    c.left_tread = 0.5f;
    c.right_tread = -2.0f;
    c.fire = true;
    c.back = true;
    const PackedCommand p = pack(c);
    EXPECT_EQ(p.left, 64);
    EXPECT_EQ(p.right, -127);
    const TickCommand u = unpack(p);
    EXPECT_NEAR(u.left_tread, 64.0f / 127.0f, 1e-6f);
    EXPECT_EQ(u.right_tread, -1.0f);
    EXPECT_TRUE(u.fire);
    EXPECT_TRUE(u.back);
    EXPECT_FALSE(u.start);
    EXPECT_EQ(pack(u), p);
    c.left_tread = std::nanf("");
    EXPECT_EQ(pack(c).left, 0);
}

TEST(TickCommand, DriveMapsToTreads) {
    TickCommand f = TickCommand::from_drive(1.0f, 0.0f);
    EXPECT_EQ(f.left_tread, 1.0f);
    EXPECT_EQ(f.right_tread, 1.0f);
    TickCommand r = TickCommand::from_drive(0.0f, 1.0f);  // spin right: left forward
    EXPECT_EQ(r.left_tread, 1.0f);
    EXPECT_EQ(r.right_tread, -1.0f);
    TickCommand m = TickCommand::from_drive(1.0f, 1.0f);
    EXPECT_LE(m.left_tread, 1.0f);
    EXPECT_EQ(m.right_tread, 0.0f);
}

TEST(Interpolation, FrameCameraMovesBetweenTicks) {
    World w = test::make_world(test::empty_level());
    w.step(test::drive(1, 1));
    w.step(test::drive(1, 1));
    const double z0 = w.interpolated_frame(0.0).camera.eye.z;
    const double zh = w.interpolated_frame(0.5).camera.eye.z;
    const double z1 = w.interpolated_frame(1.0).camera.eye.z;
    EXPECT_NEAR(z0, w.previous().player.body.transform.position.z, 1e-9);
    EXPECT_NEAR(z1, w.state().player.body.transform.position.z, 1e-9);
    EXPECT_NEAR(zh, (z0 + z1) * 0.5, 1e-9);
    EXPECT_LT(z1, z0);
}

TEST(Interpolation, WrapSeamDoesNotSweepAcrossTheField) {
    level::Level lv = test::empty_level();
    lv.field_size = 100.0;
    World w = test::make_world(lv);
    // Drive until the tank wraps from z = -50 to +50, checking the interpolated eye each tick.
    for (int i = 0; i < 60 * 8; ++i) {
        w.step(test::drive(1, 1));
        const auto mid = w.interpolated_frame(0.5).camera.eye;
        const double a = w.previous().player.body.transform.position.z;
        const double b = w.state().player.body.transform.position.z;
        const double step = std::abs(b - a) > 50.0 ? 100.0 - std::abs(b - a) : std::abs(b - a);
        EXPECT_LT(step, 0.2);
        EXPECT_TRUE(std::abs(mid.z - a) < 0.2 || std::abs(mid.z - a) > 99.0) << mid.z << " " << a;
    }
}

TEST(Interpolation, FrameDrawsObstaclesAtTheirNearestImage) {
    level::Level lv = test::empty_level();  // 400 units, wrapping
    lv.obstacles.push_back(test::object("cube", 0.0, -195.0));
    World w = test::make_world(lv);
    for (int i = 0; i < 60 * 3; ++i) w.step(test::drive(-1, -1));  // back up 21 units to z = 21
    const scene::FrameList f = w.interpolated_frame(1.0);
    ASSERT_EQ(f.items.size(), 1u);
    // 216 units away directly, 184 the other way round: drawn beyond the +z edge at 205.
    EXPECT_NEAR(f.camera.eye.z, 21.0, 0.01);
    EXPECT_NEAR(f.items[0].model[3][2], 205.0, 0.01);
}

}  // namespace
}  // namespace bz::game
