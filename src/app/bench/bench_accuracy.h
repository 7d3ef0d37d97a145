#pragma once
// The real-model accuracy suite (`bench --accuracy`): every preset (and the image-space
// baseline) draws each of a list of real models from several views; each view's line mask is
// scored against the exact CPU reference (precision, recall, F1 at a pixel tolerance) and each
// configuration's frame time on that view is measured. The stress level in `--sweep` is built
// of low-poly primitives; this suite is where touching members, thin walls, dense organic
// meshes and CAD parts show what the spine test gets wrong.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/bench_run.h"
#include "app/bench/bench_sweep.h"
#include "geometry/reference/mask_score.h"
#include "scene/frame_list.h"

namespace bz::app {

struct AccuracyModel {
    std::string path;  // relative to the models folder, or absolute
    std::string kind;  // what class of model it stands for (architecture, vehicle, ...)
};

// The default list: files under /usr/share/assimp/models (Debian assimp-testmodels) that the
// project renders, spread over formats and over the classes of model users bring.
const std::vector<AccuracyModel>& default_accuracy_models();

struct AccuracyView {
    std::string name;  // framed, behind, close, above
    scene::Camera camera;
};

// The views of a model with these bounds: `framed` is render's default 3/4 view, `behind` the
// same from the opposite side, `close` from 0.4 of the framed distance (inside the bounding
// sphere for most models: heavy occlusion, a wide near/far ratio), `above` from high up
// (roofs, decks, lids over what lies under them).
std::vector<AccuracyView> accuracy_views(const geo::Bounds& bounds, double aspect);

struct AccuracyOptions {
    std::filesystem::path models_dir = "/usr/share/assimp/models";
    std::vector<AccuracyModel> models;  // empty = default_accuracy_models()
    int width = 640;
    int height = 480;
    int tolerance_px = 1;  // Chebyshev: the 8 neighbours, i.e. 1.5 px Euclidean on the grid
    int frames = 6;        // timed frames per configuration and view
    int warmup = 1;
    std::filesystem::path out;  // masks/, diffs/ and the reference cache go here
    bool progress = true;
    // The machine's measured LineMethod::automatic crossing (app/line_method_profile.h).
    std::optional<std::size_t> auto_compute_from_triangles;
};

struct AccuracyViewScore {
    std::string model;
    std::string view;
    geo::MaskScore score;
    double p50_ms = 0.0;  // frame time of this configuration on this view
};

struct AccuracyRow {
    SweepConfig config;
    std::vector<AccuracyViewScore> views;
    double mean_f1 = 0.0, min_f1 = 1.0, mean_precision = 0.0, mean_recall = 0.0;
    double mean_p50_ms = 0.0;  // mean over the views of each view's p50 frame time
    std::string worst_view;
};

struct AccuracyViewInfo {
    std::string model;
    std::string file;
    std::string kind;
    std::string view;
    scene::Camera camera;
    std::size_t triangles = 0;
    bool reference_cached = false;
};

struct AccuracyResult {
    std::vector<AccuracyRow> rows;
    std::vector<AccuracyViewInfo> views;
    std::vector<std::string> skipped;  // models that could not be loaded, with the reason
    double reference_ms = 0.0;         // CPU time spent on reference masks (not cached ones)
};

// fast, balanced, high (each as shipped) and the image-space baseline.
std::vector<SweepConfig> accuracy_configs();

// Needs a current GL context.
AccuracyResult run_accuracy(const AccuracyOptions& options, gl::TimingMethod timing);

// The accuracy goals (mean F1, worst view, high against balanced) judged on the result.
std::vector<Goal> judge_accuracy_goals(const AccuracyResult& result);

std::string accuracy_json(const BenchMeta& meta, const AccuracyOptions& options,
                          const AccuracyResult& result, const std::vector<Goal>& goals);
void print_accuracy_table(std::FILE* out, const AccuracyResult& result,
                          const std::vector<Goal>& goals, int tolerance_px);

}  // namespace bz::app
