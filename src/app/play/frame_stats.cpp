#include "app/play/frame_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bz::app {

namespace {

constexpr double kReadoutWindow = 0.5;  // seconds: long enough to read, short enough to follow

std::string format(const char* fmt, double a, double b, double c) {
    char buf[96];
    std::snprintf(buf, sizeof buf, fmt, a, b, c);
    return buf;
}

}  // namespace

void FrameStats::add(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) return;
    frames_.push_back(static_cast<float>(seconds));
    window_seconds_ += seconds;
    window_max_ = std::max(window_max_, seconds);
    ++window_frames_;
    if (window_seconds_ >= kReadoutWindow) {
        const double fps = static_cast<double>(window_frames_) / window_seconds_;
        const double ms = 1000.0 * window_seconds_ / static_cast<double>(window_frames_);
        readout_ = format("%.0f FPS  %.1f MS  WORST %.1f MS", fps, ms, 1000.0 * window_max_);
        window_seconds_ = 0.0;
        window_frames_ = 0;
        window_max_ = 0.0;
    }
}

double FrameStats::percentile_ms(double p) const {
    if (frames_.empty()) return 0.0;
    std::vector<float> sorted = frames_;
    std::sort(sorted.begin(), sorted.end());
    const double rank =
        std::ceil(std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(sorted.size()));
    const std::size_t i = rank < 1.0 ? 0 : static_cast<std::size_t>(rank) - 1;
    return 1000.0 * sorted[std::min(i, sorted.size() - 1)];
}

std::string FrameStats::summary() const {
    if (frames_.empty()) return "frame times: no frames";
    double total = 0.0;
    for (const float f : frames_) total += f;
    const double mean_ms = 1000.0 * total / static_cast<double>(frames_.size());
    return "frame times over " + std::to_string(frames_.size()) + " frames: " +
           format("mean %.2f ms (%.1f fps), p50 %.2f ms, ", mean_ms,
                  mean_ms > 0.0 ? 1000.0 / mean_ms : 0.0, percentile_ms(50)) +
           format("p90 %.2f ms, p99 %.2f ms, max %.2f ms", percentile_ms(90), percentile_ms(99),
                  percentile_ms(100));
}

}  // namespace bz::app
