#include "app/bench/bench_stats.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace bz::app {

double percentile(std::span<const double> values, double pct) {
    if (values.empty()) return 0.0;
    std::vector<double> v(values.begin(), values.end());
    std::sort(v.begin(), v.end());
    const double rank = std::ceil(pct / 100.0 * static_cast<double>(v.size()));
    const auto i =
        static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(v.size()))) - 1;
    return v[i];
}

FrameTimeStats frame_time_stats(std::span<const double> ms) {
    FrameTimeStats s;
    s.frames = ms.size();
    if (ms.empty()) return s;
    std::vector<double> v(ms.begin(), ms.end());
    std::sort(v.begin(), v.end());
    s.mean_ms = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    s.p50_ms = percentile(v, 50.0);
    s.p95_ms = percentile(v, 95.0);
    s.p99_ms = percentile(v, 99.0);
    s.max_ms = v.back();
    s.min_ms = v.front();
    const std::size_t worst = std::max<std::size_t>(1, v.size() / 100);
    const double worst_mean =
        std::accumulate(v.end() - static_cast<std::ptrdiff_t>(worst), v.end(), 0.0) /
        static_cast<double>(worst);
    s.low_1pct_fps = worst_mean > 0.0 ? 1000.0 / worst_mean : 0.0;
    s.mean_fps = s.mean_ms > 0.0 ? 1000.0 / s.mean_ms : 0.0;
    return s;
}

LineFit fit_line(std::span<const double> x, std::span<const double> y) {
    LineFit f;
    const std::size_t n = std::min(x.size(), y.size());
    if (n == 0) return f;
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    double sxx = 0.0, sxy = 0.0, syy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
        syy += (y[i] - my) * (y[i] - my);
    }
    f.slope = sxx > 0.0 ? sxy / sxx : 0.0;
    f.intercept = my - f.slope * mx;
    f.r2 = sxx > 0.0 && syy > 0.0 ? (sxy * sxy) / (sxx * syy) : 0.0;
    return f;
}

}  // namespace bz::app
