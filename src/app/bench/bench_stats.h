#pragma once
// Frame-time statistics, defined once here and in docs/benchmark.md:
//  - mean: arithmetic mean of the frame times;
//  - pN: the nearest-rank percentile: the smallest frame time t such that at least N% of the
//    frames took <= t (p50 is the median);
//  - max: the slowest frame;
//  - 1% low FPS: 1000 / (mean of the slowest 1% of frame times, at least one frame), the
//    frame rate of the worst stretch a player notices.
#include <span>

namespace bz::app {

struct FrameTimeStats {
    std::size_t frames = 0;
    double mean_ms = 0.0;
    double p50_ms = 0.0;
    double p95_ms = 0.0;
    double p99_ms = 0.0;
    double max_ms = 0.0;
    double min_ms = 0.0;
    double low_1pct_fps = 0.0;
    double mean_fps = 0.0;  // 1000 / mean_ms
};

// Nearest-rank percentile of unsorted values, 0 < pct <= 100; 0 for no values.
double percentile(std::span<const double> values, double pct);
FrameTimeStats frame_time_stats(std::span<const double> frame_ms);

// Least-squares slope and intercept of y over x; slope 0 when x does not vary.
struct LineFit {
    double slope = 0.0;
    double intercept = 0.0;
    double r2 = 0.0;
};
LineFit fit_line(std::span<const double> x, std::span<const double> y);

}  // namespace bz::app
