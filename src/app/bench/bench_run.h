#pragma once
// One timed benchmark run: a renderer drawing a fixed list of frames offscreen, every pass
// timed by name, frame times taken around each whole frame.
#include <functional>
#include <string>
#include <vector>

#include "app/bench/bench_stats.h"
#include "render/renderer.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::app {

// The frames of a benchmark, simulated once so that every configuration draws the same ones.
struct BenchFrames {
    std::vector<scene::FrameList> frames;  // warm-up frames first
    std::vector<double> seconds;           // simulated time of each
    int warmup = 0;
};

struct FrameRecord {
    int frame = 0;                // 0 = the first timed frame
    double seconds = 0.0;         // simulated time
    double ms_between = 0.0;      // this frame's start to the next one's (MsBetweenPresents)
                                  // (the last of a stretch: to the end of its glFinish)
    double ms_cpu_busy = 0.0;     // until render() returned; glFinish waits after it
    std::vector<double> pass_ms;  // in RunResult::pass_names order; < 0 when not reported
    render::FrameStats stats;
};

struct RunResult {
    std::string label;
    render::RenderSettings settings;
    gl::TimingMethod timing = gl::TimingMethod::off;
    std::vector<std::string> pass_names;
    std::vector<FrameRecord> frames;
    FrameTimeStats stats;  // over ms_between
};

// The mean of one pass's time over a run's timed frames (0 when it never ran).
double mean_pass_ms(const RunResult& run, const std::string& pass);

// The mean of one FrameStats value over a run's timed frames (0 without frames).
template <class Value>
double mean_frame_stat(const RunResult& run, Value value) {
    double sum = 0.0;
    for (const FrameRecord& f : run.frames) sum += static_cast<double>(value(f.stats));
    return run.frames.empty() ? 0.0 : sum / static_cast<double>(run.frames.size());
}

// Feature edges per frame, mean over the run's timed frames.
inline double mean_feature_edges(const RunResult& run) {
    return mean_frame_stat(run, [](const render::FrameStats& f) { return f.feature_edges; });
}

// Called after every timed frame.
using Progress = std::function<void()>;

// Renders every frame (warm-up ones untimed) with `settings`, reading pass times `latency`
// frames late for timer queries (extra frames are drawn at the end to flush them).
RunResult run_frames(render::Renderer& renderer, const BenchFrames& frames,
                     const scene::MeshLibrary& meshes, const std::string& label,
                     const render::RenderSettings& settings, const Progress& progress);

// The same in pieces, for interleaving several configurations so that a machine whose load
// drifts during the run treats them alike: start_run() once, run_chunk() for consecutive
// stretches of timed frames (each after `warm` untimed frames that lead into it), then
// finish_run() for the statistics.
RunResult start_run(const BenchFrames& frames, const std::string& label,
                    const render::RenderSettings& settings);
void run_chunk(render::Renderer& renderer, const BenchFrames& frames,
               const scene::MeshLibrary& meshes, int first, int count, int warm, RunResult& run,
               const Progress& progress);
void finish_run(RunResult& run);

// A text progress bar on stderr: redrawn in place on a terminal, one line per run otherwise.
class ProgressBar {
  public:
    ProgressBar(std::string label, int total);
    void operator()();  // one more step done

  private:
    std::string label_;
    int total_;
    int done_ = 0;
    bool tty_;
    double last_draw_ = -1.0;
};

}  // namespace bz::app
