#include "app/bench/bench_run.h"

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

RunResult start_run(const BenchFrames& bf, const std::string& label,
                    const render::RenderSettings& settings) {
    RunResult out;
    out.label = label;
    out.settings = settings;
    out.frames.resize(
        static_cast<std::size_t>(std::max(0, static_cast<int>(bf.frames.size()) - bf.warmup)));
    for (std::size_t k = 0; k < out.frames.size(); ++k) {
        out.frames[k].frame = static_cast<int>(k);
        out.frames[k].seconds = bf.seconds[k + static_cast<std::size_t>(bf.warmup)];
    }
    return out;
}

void run_chunk(render::Renderer& r, const BenchFrames& bf, const scene::MeshLibrary& meshes,
               int first, int count, int warm, RunResult& run, const Progress& progress) {
    r.set_settings(run.settings);
    run.timing = r.timing_method();
    const int latency = r.pass_times_latency();
    // Draw calls cover list frames [begin, end); pass times for call i arrive after call
    // i + latency, so the last frame is drawn `latency` more times, untimed, to flush them.
    const int end = bf.warmup + first + count;
    const int begin = std::max(0, bf.warmup + first - warm);
    const int last = static_cast<int>(bf.frames.size()) - 1;
    std::vector<Clock::time_point> starts(static_cast<std::size_t>(count) + 1);
    for (int i = begin; i < end + latency; ++i) {
        const bool timed = i >= bf.warmup + first && i < end;
        const scene::FrameList& f =
            bf.frames[static_cast<std::size_t>(std::min({i, end - 1, last}))];
        const int k = i - bf.warmup;  // timed frame number
        const Clock::time_point t0 = Clock::now();
        if (timed) starts[static_cast<std::size_t>(i - (bf.warmup + first))] = t0;
        r.render(f, meshes, render::Renderer::kOffscreen);
        const Clock::time_point t1 = Clock::now();
        glFinish();  // the frame is done: what a present with no queued frames waits for
        if (timed) {
            FrameRecord& rec = run.frames[static_cast<std::size_t>(k)];
            rec.ms_cpu_busy = ms_since(t0, t1);
            rec.stats = r.stats();
            if (i == end - 1) starts.back() = Clock::now();
        }
        const int reported = k - latency;  // the timed frame whose pass times just arrived
        if (i - latency >= bf.warmup + first && i - latency < end) {
            FrameRecord& rec = run.frames[static_cast<std::size_t>(reported)];
            // Its feature-edge count arrives with them (render::EdgeCounter, same latency).
            rec.stats.feature_edges = r.stats().feature_edges;
            for (const gl::PassTime& p : r.pass_times()) {
                const std::size_t c = column(run.pass_names, p.name);
                if (rec.pass_ms.size() <= c) rec.pass_ms.resize(c + 1, -1.0);
                rec.pass_ms[c] = p.ms;
            }
        }
        if (progress && timed) progress();
    }
    for (int j = 0; j < count; ++j) {
        run.frames[static_cast<std::size_t>(first + j)].ms_between =
            ms_since(starts[static_cast<std::size_t>(j)], starts[static_cast<std::size_t>(j) + 1]);
    }
}

void finish_run(RunResult& run) {
    std::vector<double> ms;
    for (FrameRecord& f : run.frames) {
        f.pass_ms.resize(run.pass_names.size(), -1.0);
        ms.push_back(f.ms_between);
    }
    run.stats = frame_time_stats(ms);
}

RunResult run_frames(render::Renderer& r, const BenchFrames& bf, const scene::MeshLibrary& meshes,
                     const std::string& label, const render::RenderSettings& settings,
                     const Progress& progress) {
    RunResult out = start_run(bf, label, settings);
    run_chunk(r, bf, meshes, 0, static_cast<int>(out.frames.size()), bf.warmup, out, progress);
    finish_run(out);
    return out;
}

ProgressBar::ProgressBar(std::string label, int total)
    : label_(std::move(label)), total_(total), tty_(isatty(STDERR_FILENO) != 0) {}

void ProgressBar::operator()() {
    ++done_;
    if (total_ <= 0) return;
    const double now = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    const bool last = done_ == total_;
    if (!tty_) {
        if (last) std::fprintf(stderr, "%-28s %d done\n", label_.c_str(), total_);
        return;
    }
    if (!last && now - last_draw_ < 0.1) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = std::min(done_, total_) * kWidth / total_;
    std::fprintf(stderr, "\r%-28s [%s%s] %d/%d", label_.c_str(),
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), '.').c_str(), done_,
                 total_);
    if (last) std::fputc('\n', stderr);
    std::fflush(stderr);
}

double mean_pass_ms(const RunResult& run, const std::string& pass) {
    std::size_t index = run.pass_names.size();
    for (std::size_t i = 0; i < run.pass_names.size(); ++i)
        if (run.pass_names[i] == pass) index = i;
    double sum = 0.0;
    int n = 0;
    for (const FrameRecord& f : run.frames) {
        if (index < f.pass_ms.size() && f.pass_ms[index] >= 0.0) {
            sum += f.pass_ms[index];
            ++n;
        }
    }
    return n > 0 ? sum / n : 0.0;
}

}  // namespace bz::app
