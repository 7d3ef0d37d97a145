#include "app/bench/bench_stats.h"

#include <gtest/gtest.h>

#include <vector>

namespace bz::app {
namespace {

TEST(BenchStats, NearestRankPercentiles) {
    std::vector<double> v;
    for (int i = 100; i >= 1; --i) v.push_back(i);  // 1..100, unsorted
    EXPECT_EQ(percentile(v, 50.0), 50.0);
    EXPECT_EQ(percentile(v, 95.0), 95.0);
    EXPECT_EQ(percentile(v, 99.0), 99.0);
    EXPECT_EQ(percentile(v, 100.0), 100.0);
    EXPECT_EQ(percentile(v, 0.1), 1.0);
    EXPECT_EQ(percentile(std::vector<double>{}, 50.0), 0.0);
    EXPECT_EQ(percentile(std::vector<double>{7.0}, 99.0), 7.0);
}

TEST(BenchStats, FrameTimeSummary) {
    // 198 frames of 10 ms and two of 50 ms: the slowest 1% is the two 50 ms frames.
    std::vector<double> ms(198, 10.0);
    ms.insert(ms.begin() + 50, 50.0);
    ms.push_back(50.0);
    const FrameTimeStats s = frame_time_stats(ms);
    EXPECT_EQ(s.frames, 200u);
    EXPECT_DOUBLE_EQ(s.mean_ms, (198 * 10.0 + 100.0) / 200.0);
    EXPECT_EQ(s.p50_ms, 10.0);
    EXPECT_EQ(s.p95_ms, 10.0);
    EXPECT_EQ(s.p99_ms, 10.0);  // rank 198 of 200
    EXPECT_EQ(s.max_ms, 50.0);
    EXPECT_EQ(s.min_ms, 10.0);
    EXPECT_DOUBLE_EQ(s.low_1pct_fps, 20.0);
    EXPECT_DOUBLE_EQ(s.mean_fps, 1000.0 / s.mean_ms);
}

TEST(BenchStats, FewFramesStillHaveAOnePercentLow) {
    const FrameTimeStats s = frame_time_stats(std::vector<double>{4.0, 8.0, 5.0});
    EXPECT_DOUBLE_EQ(s.low_1pct_fps, 125.0);  // the single slowest frame
    EXPECT_EQ(frame_time_stats(std::vector<double>{}).frames, 0u);
}

TEST(BenchStats, LineFit) {
    const std::vector<double> x{1.0, 2.0, 3.0, 4.0}, y{3.0, 5.0, 7.0, 9.0};
    const LineFit f = fit_line(x, y);
    EXPECT_DOUBLE_EQ(f.slope, 2.0);
    EXPECT_DOUBLE_EQ(f.intercept, 1.0);
    EXPECT_DOUBLE_EQ(f.r2, 1.0);
    EXPECT_EQ(fit_line(std::vector<double>{2.0, 2.0}, std::vector<double>{1.0, 3.0}).slope, 0.0);
}

}  // namespace
}  // namespace bz::app
