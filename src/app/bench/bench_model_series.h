#pragma once
// The model series of `bench --scaling`: one model at about 20k, 80k, 320k and 1.3M triangles
// (a sphere tessellated ever finer, so its silhouette grows as the square root of its
// triangles), each drawn from the same view, to show what the edges pass costs against the
// triangles submitted and against the silhouette it finds.
#include <string>
#include <vector>

#include "app/bench/bench_run.h"
#include "app/json_text.h"

namespace bz::app {

struct SeriesPoint {
    std::size_t triangles = 0;
    double frame_p50_ms = 0.0;
    double edges_ms = 0.0;  // the edges pass, mean over the timed frames (compute only)
    double prepass_ms = 0.0;
    double feature_edges = 0.0;      // mean per frame: the silhouette (a sphere has no crease)
    double edges_tested = 0.0;       // mean per frame: edges culling left to the edges pass
    double prepass_triangles = 0.0;  // mean per frame: triangles cluster culling drew
};

struct ModelSeries {
    std::vector<SeriesPoint> points;
    std::string method;  // the line method the series drew with
};

// `settings`: the run's settings; the series draws with LineMethod::compute (the method whose
// edges pass it measures). `frames` timed frames after 2 warm-up ones per model; only sizes
// of at most `max_triangles`.
ModelSeries run_model_series(const render::RenderSettings& settings, int width, int height,
                             gl::TimingMethod timing, int frames, std::size_t max_triangles,
                             bool show_progress);

Json model_series_json(const ModelSeries& series);
void print_model_series(std::FILE* out, const ModelSeries& series);

}  // namespace bz::app
