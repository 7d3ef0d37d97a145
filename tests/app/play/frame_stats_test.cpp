#include "app/play/frame_stats.h"

#include <gtest/gtest.h>

namespace bz::app {
namespace {

TEST(FrameStats, PercentilesByNearestRank) {
    FrameStats s;
    for (int i = 1; i <= 100; ++i) s.add(i / 1000.0);  // 1..100 ms
    EXPECT_EQ(s.count(), 100u);
    EXPECT_NEAR(s.percentile_ms(50), 50.0, 1e-3);
    EXPECT_NEAR(s.percentile_ms(90), 90.0, 1e-3);
    EXPECT_NEAR(s.percentile_ms(99), 99.0, 1e-3);
    EXPECT_NEAR(s.percentile_ms(100), 100.0, 1e-3);
    EXPECT_NEAR(s.percentile_ms(0), 1.0, 1e-3);
    const std::string text = s.summary();
    EXPECT_NE(text.find("over 100 frames"), std::string::npos) << text;
    EXPECT_NE(text.find("p99 99.00 ms"), std::string::npos) << text;
}

TEST(FrameStats, ReadoutEveryHalfSecond) {
    FrameStats s;
    EXPECT_TRUE(s.readout().empty());
    for (int i = 0; i < 29; ++i) s.add(1.0 / 60.0);
    EXPECT_TRUE(s.readout().empty());
    for (int i = 0; i < 2; ++i) s.add(1.0 / 60.0);  // 31 frames: past half a second
    EXPECT_EQ(s.readout().rfind("60 FPS  16.7 MS", 0), 0u) << s.readout();
}

TEST(FrameStats, IgnoresNonsense) {
    FrameStats s;
    s.add(-1.0);
    s.add(std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(s.count(), 0u);
    EXPECT_EQ(s.summary(), "frame times: no frames");
}

}  // namespace
}  // namespace bz::app
