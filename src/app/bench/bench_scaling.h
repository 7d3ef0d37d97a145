#pragma once
// Scaling: the same frames drawn from meshes with 1x, 4x, 16x and 64x the triangles (flat
// subdivision: same surfaces, same feature lines), to measure the cost per triangle.
#include <string>
#include <vector>

#include "app/bench/bench_model_series.h"
#include "app/bench/bench_plots.h"
#include "app/bench/bench_report.h"
#include "app/bench/bench_run.h"

namespace bz::app {

struct ScalingResult {
    std::vector<ScalingPoint> points;
    std::vector<RunResult> runs;
    LineFit fit;                       // p50 ms over triangles submitted per frame
    std::vector<std::string> skipped;  // factors left out, and why
    ModelSeries series;                // the model series (run_model_series), when run
};

// `max_library_triangles` caps the subdivided library's size (memory): larger factors are
// skipped and named in `skipped`.
ScalingResult run_scaling(const BenchFrames& frames, const scene::MeshLibrary& meshes,
                          const render::RenderSettings& settings, int width, int height,
                          gl::TimingMethod timing, std::size_t max_library_triangles,
                          bool show_progress);

std::string scaling_json(const BenchMeta& meta, const ScalingResult& result);

}  // namespace bz::app
