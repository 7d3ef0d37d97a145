#pragma once
// The speed-accuracy sweep: every preset, the image-space outline baseline and the scene
// modelling switches (frustum culling, distance LOD, instancing) on the same frames, each
// timed and, at sampled frames, scored against the exact CPU reference.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/bench_goals.h"
#include "app/bench/bench_plots.h"
#include "app/bench/bench_report.h"
#include "app/bench/bench_run.h"
#include "geometry/reference/mask_score.h"
#include "scene/mesh_library.h"

namespace bz::app {

struct SweepConfig {
    std::string label;
    std::string what;  // one line: what differs
    render::RenderSettings settings;
};

// fast, balanced, high (the default line method), each preset with the other line method,
// image-outline, balanced with culling / LOD / instancing off, and every style
// (scene::all_styles) with the balanced preset.
std::vector<SweepConfig> sweep_configs();

struct SweepScore {
    double mean_f1 = 0.0;
    double min_f1 = 1.0;
    double mean_precision = 0.0;
    double mean_recall = 0.0;
    std::vector<geo::MaskScore> per_sample;
};

struct SweepRow {
    SweepConfig config;
    RunResult run;
    SweepScore score;      // at 1 px
    SweepScore score_2px;  // the same masks at 2 and 4 px (for the sketch style's jitter)
    SweepScore score_4px;
};

// The sweep's goals, judged on the measured rows (missing rows make a goal unmet).
std::vector<Goal> judge_goals(const std::vector<SweepRow>& rows);

struct SweepOptions {
    int samples = 6;  // frames scored against the reference
    // The timed frames are split into this many stretches, run round-robin over the
    // configurations (each with its own renderer), so load that drifts during a long run on a
    // shared machine does not favour whichever configuration ran when it was quiet.
    int rounds = 4;
    int warm_per_stretch = 5;         // untimed frames leading into each later stretch
    std::filesystem::path masks_dir;  // where sampled masks are written; empty = nowhere
    bool progress = true;
    // The machine's measured LineMethod::automatic crossing (app/line_method_profile.h).
    std::optional<std::size_t> auto_compute_from_triangles;
    // The level's [render] material_lines: every row but the material-lines ones (which turn
    // them on) draws them as the level asks, and is scored against a reference that does too.
    bool material_lines = false;
    // The level's [render] intersection_lines, likewise.
    bool intersection_lines = false;
};

struct SweepResult {
    std::vector<SweepRow> rows;
    std::vector<int> sampled;  // timed-frame numbers scored
    // Their simulated times: `reference --level LEVEL --time T` rebuilds the same frame.
    std::vector<double> sampled_seconds;
    double reference_ms = 0.0;  // CPU time of all reference masks
    std::size_t reference_rays = 0;
};

// Runs every configuration on `frames` (already simulated). Reference masks are computed once
// per sampled frame.
SweepResult run_sweep(const BenchFrames& frames, const scene::MeshLibrary& meshes, int width,
                      int height, gl::TimingMethod timing, const SweepOptions& options);

std::string sweep_json(const BenchMeta& meta, const SweepResult& result,
                       const std::vector<Goal>& goals);
void print_sweep_table(std::FILE* out, const SweepResult& result, const std::vector<Goal>& goals);

// The frames (timed-frame numbers) a sweep scores: `samples` spread evenly.
std::vector<int> sampled_frames(int timed_frames, int samples);

}  // namespace bz::app
