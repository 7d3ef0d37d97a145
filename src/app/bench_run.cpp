#include "app/bench_run.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace bz::app {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

std::size_t column(std::vector<std::string>& names, const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
    names.push_back(name);
    return names.size() - 1;
}

}  // namespace

RunResult run_frames(render::Renderer& r, const BenchFrames& bf, const scene::MeshLibrary& meshes,
                     const std::string& label, const render::RenderSettings& settings,
                     const Progress& progress) {
    RunResult out;
    out.label = label;
    out.settings = settings;
    r.set_settings(settings);
    out.timing = r.timing_method();
    const int total = static_cast<int>(bf.frames.size());
    const int latency = r.pass_times_latency();
    std::vector<Clock::time_point> starts;
    starts.reserve(static_cast<std::size_t>(total) + 1);
    out.frames.resize(static_cast<std::size_t>(std::max(0, total - bf.warmup)));

    // Pass times for draw call i arrive after draw call i + latency; drawing the last frame
    // again `latency` times at the end collects them without timing those extra draws.
    for (int i = 0; i < total + latency; ++i) {
        const bool timed = i < total;
        const scene::FrameList& f = bf.frames[static_cast<std::size_t>(std::min(i, total - 1))];
        const Clock::time_point t0 = Clock::now();
        if (timed) starts.push_back(t0);
        r.render(f, meshes, render::Renderer::kOffscreen);
        const Clock::time_point t1 = Clock::now();
        glFinish();  // the frame is done: what a present with no queued frames waits for
        if (timed && i >= bf.warmup) {
            FrameRecord& rec = out.frames[static_cast<std::size_t>(i - bf.warmup)];
            rec.frame = i - bf.warmup;
            rec.seconds = bf.seconds[static_cast<std::size_t>(i)];
            rec.ms_cpu_busy = ms_since(t0, t1);
            rec.stats = r.stats();
        }
        const int timed_frame = i - latency - bf.warmup;
        if (timed_frame >= 0 && timed_frame < static_cast<int>(out.frames.size())) {
            FrameRecord& rec = out.frames[static_cast<std::size_t>(timed_frame)];
            for (const gl::PassTime& p : r.pass_times()) {
                const std::size_t c = column(out.pass_names, p.name);
                if (rec.pass_ms.size() <= c) rec.pass_ms.resize(c + 1, -1.0);
                rec.pass_ms[c] = p.ms;
            }
        }
        if (progress && timed) progress(i + 1, total);
    }
    starts.push_back(Clock::now());
    for (std::size_t k = 0; k < out.frames.size(); ++k) {
        const std::size_t i = k + static_cast<std::size_t>(bf.warmup);
        out.frames[k].ms_between = ms_since(starts[i], starts[i + 1]);
        out.frames[k].pass_ms.resize(out.pass_names.size(), -1.0);
    }
    std::vector<double> ms;
    for (const FrameRecord& f : out.frames) ms.push_back(f.ms_between);
    out.stats = frame_time_stats(ms);
    return out;
}

ProgressBar::ProgressBar(std::string label) : label_(std::move(label)), tty_(isatty(STDERR_FILENO) != 0) {}

void ProgressBar::operator()(int done, int total) {
    if (total <= 0) return;
    const double now = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    const bool last = done >= total;
    if (!tty_) {
        if (last) std::fprintf(stderr, "%-28s %d frames done\n", label_.c_str(), total);
        return;
    }
    if (!last && now - last_draw_ < 0.1) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = done * kWidth / total;
    std::fprintf(stderr, "\r%-28s [%s%s] %d/%d", label_.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), done, total);
    if (last) std::fputc('\n', stderr);
    std::fflush(stderr);
}

}  // namespace bz::app
