#pragma once
// What a benchmark writes: frames.csv (one row per frame, PresentMon-like column names),
// summary.json, and the summary table on stdout.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/bench/bench_run.h"
#include "app/json_text.h"

namespace bz::app {

struct BenchMeta {
    std::string level;
    std::string camera;
    int width = 0;
    int height = 0;
    int frames = 0;
    int warmup = 0;
    std::string gl_renderer;
    bool software = false;
    gl::TimingMethod timing = gl::TimingMethod::off;
    double load_before = -1.0;  // 1-minute load average, -1 if unknown
    double load_after = -1.0;
    Json auto_line_method;  // line_method_profile_json: LineMethod::automatic's crossing
    // The path colour clears took (render/clear_image.h) and, where auto timed both, their
    // times: {"path": "compute", "measured_ms": {...}}; null: not said (sweep, scaling).
    Json colour_clears;
    // How the last frame's mip-chain bloom went past level 0 (render::BloomChainSplit):
    // {"levels_drawn": D, "levels_walked": W}; null: no mip chain, or not said.
    Json bloom_chain;
};

// "cpu_finish" / "gpu_queries" and a sentence on what it measures.
const char* timing_name(gl::TimingMethod m);
const char* timing_note(gl::TimingMethod m);
// The 1-minute load average from /proc/loadavg, or -1.
double load_average();

// Columns: Config, Frame, TimeInSeconds, MsBetweenPresents, MsCPUBusy, MsPass_<name>...,
// ObjectsDrawn, ObjectsCulled, TrianglesSubmitted, FeatureEdges.
std::string frames_csv(const std::vector<RunResult>& runs);

// The fields every report starts with, and one run's settings and statistics.
Json meta_json(const BenchMeta& meta);
Json run_json(const RunResult& run);
std::string summary_json(const BenchMeta& meta, const std::vector<RunResult>& runs);

void print_summary_table(std::FILE* out, const BenchMeta& meta, const std::vector<RunResult>& runs);

// Mean of one pass's times over a run's frames (frames that did not report it are skipped).
double mean_pass_ms(const RunResult& run, std::size_t pass);

}  // namespace bz::app
