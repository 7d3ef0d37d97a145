#pragma once
// The benchmark's pictures, drawn with the tiny rasteriser in plot_canvas.h.
#include <filesystem>
#include <string>
#include <vector>

#include "app/bench/bench_run.h"
#include "app/bench/bench_stats.h"
#include "scene/vector_font.h"

namespace bz::app {

// Frame time per frame, stacked by pass, with the whole frame's time as a line on top (the
// gap is CPU work outside the timed passes).
void plot_frame_times(const RunResult& run, const std::string& title, const scene::VectorFont* font,
                      const std::filesystem::path& out);

struct TradeoffPoint {
    std::string label;
    double p50_ms = 0.0;
    double mean_f1 = 0.0;
    double min_f1 = 0.0;
};
// p50 frame time against mean F1, one labelled point per configuration (a bar down to min F1).
void plot_tradeoff(const std::vector<TradeoffPoint>& points, const std::string& title,
                   const scene::VectorFont* font, const std::filesystem::path& out);

struct ScalingPoint {
    std::string label;
    double triangles = 0.0;  // submitted per frame
    double p50_ms = 0.0;
};
void plot_scaling(const std::vector<ScalingPoint>& points, const LineFit& fit,
                  const std::string& title, const scene::VectorFont* font,
                  const std::filesystem::path& out);

}  // namespace bz::app
