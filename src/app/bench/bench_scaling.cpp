#include "app/bench/bench_scaling.h"

#include <cstdio>

#include "core/error.h"
#include "geometry/generated/subdivide.h"

namespace bz::app {

namespace {

std::size_t library_triangles(const scene::MeshLibrary& lib) {
    std::size_t n = 0;
    for (scene::MeshId id = 0; id < lib.size(); ++id) n += lib.mesh(id).triangle_count();
    return n;
}

// The same ids with every mesh subdivided.
scene::MeshLibrary subdivided(const scene::MeshLibrary& src, int levels) {
    scene::MeshLibrary out;
    for (scene::MeshId id = 0; id < src.size(); ++id) {
        const scene::MeshId added =
            out.add(src.name(id), geo::subdivide_flat(src.mesh(id), levels));
        if (added != id) throw std::logic_error("subdivided library: mesh ids moved");
    }
    return out;
}

}  // namespace

ScalingResult run_scaling(const BenchFrames& bf, const scene::MeshLibrary& meshes,
                          const render::RenderSettings& settings, int width, int height,
                          gl::TimingMethod timing, std::size_t max_tris, bool show_progress) {
    ScalingResult r;
    const std::size_t base = library_triangles(meshes);
    std::vector<double> xs, ys;
    for (int level = 0; level <= 3; ++level) {
        const std::size_t factor = std::size_t{1} << (2 * level);
        const std::string label = std::to_string(factor) + "x";
        if (base * factor > max_tris) {
            r.skipped.push_back(label + ": " + std::to_string(base * factor) +
                                " triangles in the library, over the " + std::to_string(max_tris) +
                                " cap");
            continue;
        }
        // A fresh renderer per library: GPU meshes are cached by id, and the ids repeat.
        const scene::MeshLibrary lib =
            level == 0 ? scene::MeshLibrary{} : subdivided(meshes, level);
        const scene::MeshLibrary& use = level == 0 ? meshes : lib;
        render::Renderer fresh(settings, width, height, timing);
        ProgressBar bar("scaling " + label, static_cast<int>(bf.frames.size()) - bf.warmup);
        Progress progress;
        if (show_progress) progress = [&bar] { bar(); };
        RunResult run = run_frames(fresh, bf, use, "scaling-" + label, settings, progress);
        double tris = 0.0;
        for (const FrameRecord& f : run.frames)
            tris += static_cast<double>(f.stats.triangles_submitted);
        tris /= static_cast<double>(std::max<std::size_t>(run.frames.size(), 1));
        r.points.push_back({label, tris, run.stats.p50_ms});
        xs.push_back(tris);
        ys.push_back(run.stats.p50_ms);
        r.runs.push_back(std::move(run));
    }
    r.fit = fit_line(xs, ys);
    return r;
}

std::string scaling_json(const BenchMeta& meta, const ScalingResult& r) {
    Json j = meta_json(meta);
    j["method"] = "every mesh flat-subdivided 1 -> 4 per level: same surfaces and feature lines";
    Json points = Json::array();
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        Json p = Json::object();
        p["factor"] = r.points[i].label;
        p["triangles_submitted_mean"] = r.points[i].triangles;
        p["edges_pass_ms_mean"] = mean_pass_ms(r.runs[i], "edges");
        p["feature_edges_mean"] = mean_feature_edges(r.runs[i]);
        p.update(run_json(r.runs[i]));
        points.push_back(std::move(p));
    }
    j["points"] = std::move(points);
    j["fit"] = Json{{"ms_per_100k_triangles", r.fit.slope * 1e5},
                    {"intercept_ms", r.fit.intercept},
                    {"r2", r.fit.r2}};
    j["skipped"] = r.skipped;
    if (!r.series.points.empty()) j["model_series"] = model_series_json(r.series);
    return json_text(j);
}

}  // namespace bz::app
