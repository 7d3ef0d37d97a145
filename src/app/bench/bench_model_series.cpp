#include "app/bench/bench_model_series.h"

#include <cstdio>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"
#include "render/camera/camera_framing.h"

namespace bz::app {

namespace {

// Rings of the uv spheres (segments twice as many): about 20k, 80k, 320k and 1.3M triangles.
constexpr std::uint32_t kRings[] = {71, 142, 284, 570};

}  // namespace

ModelSeries run_model_series(const render::RenderSettings& settings, int width, int height,
                             gl::TimingMethod timing, int frames, std::size_t max_triangles,
                             bool show_progress) {
    ModelSeries out;
    render::RenderSettings s = settings;
    s.method = render::LineMethod::compute;
    s.count_edges = true;
    s.lod = false;  // the whole model at every size
    out.method = render::line_method_name(s.method);
    for (const std::uint32_t rings : kRings) {
        // A uv sphere of r rings has 2 r (2 r - 2) triangles (one fan at each pole).
        if (std::size_t{4} * rings * rings > max_triangles + std::size_t{4} * rings) break;
        scene::MeshLibrary meshes;
        geo::AdjacencyMesh mesh = geo::build_line_mesh(geo::uv_sphere(1.0f, rings, rings * 2));
        const std::size_t triangles = mesh.triangle_count();
        const geo::Bounds bounds = geo::compute_bounds(mesh.positions);
        scene::FrameList frame;
        frame.items.push_back(
            {meshes.add("series sphere " + std::to_string(rings), std::move(mesh))});
        frame.camera = render::frame_bounds(bounds, 50.0, static_cast<double>(width) / height);
        BenchFrames bf;
        bf.warmup = 2;
        for (int i = 0; i < frames + bf.warmup; ++i) {
            frame.time_s = i / 60.0;
            bf.frames.push_back(frame);
            bf.seconds.push_back(frame.time_s);
        }
        render::Renderer renderer(s, width, height, timing);
        const std::string label = "series-" + std::to_string(triangles);
        ProgressBar bar(label, frames);
        Progress progress;
        if (show_progress) progress = [&bar] { bar(); };
        const RunResult run = run_frames(renderer, bf, meshes, label, s, progress);
        SeriesPoint p;
        p.triangles = triangles;
        p.frame_p50_ms = run.stats.p50_ms;
        p.edges_ms = mean_pass_ms(run, "edges");
        p.prepass_ms = mean_pass_ms(run, "prepass");
        p.feature_edges = mean_feature_edges(run);
        p.edges_tested = mean_frame_stat(
            run, [](const render::FrameStats& f) { return f.edge_culling.edges_dispatched; });
        p.prepass_triangles = mean_frame_stat(run, [](const render::FrameStats& f) {
            return f.triangle_culling.clusters > 0 ? f.triangle_culling.triangles_drawn
                                                   : f.triangles_submitted;
        });
        out.points.push_back(p);
    }
    return out;
}

Json model_series_json(const ModelSeries& series) {
    Json j = Json::object();
    j["model"] = "uv sphere, radius 1, framed at 50 degrees; rings x 2 rings segments";
    j["line_method"] = series.method;
    Json points = Json::array();
    for (const SeriesPoint& p : series.points) {
        Json e = Json::object();
        e["triangles"] = p.triangles;
        e["frame_p50_ms"] = p.frame_p50_ms;
        e["edges_pass_ms"] = p.edges_ms;
        e["prepass_ms"] = p.prepass_ms;
        e["feature_edges"] = p.feature_edges;
        e["edges_tested"] = p.edges_tested;
        e["prepass_triangles_drawn"] = p.prepass_triangles;
        e["edges_pass_us_per_feature_edge"] =
            p.feature_edges > 0.0 ? p.edges_ms * 1000.0 / p.feature_edges : 0.0;
        points.push_back(std::move(e));
    }
    j["points"] = std::move(points);
    if (series.points.size() >= 2 && series.points.front().edges_ms > 0.0) {
        j["edges_pass_largest_over_smallest"] =
            series.points.back().edges_ms / series.points.front().edges_ms;
        j["triangles_largest_over_smallest"] = static_cast<double>(series.points.back().triangles) /
                                               static_cast<double>(series.points.front().triangles);
    }
    return j;
}

void print_model_series(std::FILE* out, const ModelSeries& series) {
    std::fprintf(out,
                 "\nmodel series (a sphere, %s line method): the edges pass against the "
                 "silhouette\n",
                 series.method.c_str());
    std::fprintf(out, "%10s %9s %9s %11s %9s %9s %10s\n", "triangles", "frame p50", "edges ms",
                 "us/feature", "features", "tested", "prepass ms");
    for (const SeriesPoint& p : series.points) {
        std::fprintf(out, "%10zu %9.2f %9.2f %11.3f %9.0f %9.0f %10.2f\n", p.triangles,
                     p.frame_p50_ms, p.edges_ms,
                     p.feature_edges > 0.0 ? p.edges_ms * 1000.0 / p.feature_edges : 0.0,
                     p.feature_edges, p.edges_tested, p.prepass_ms);
    }
    if (series.points.size() >= 2 && series.points.front().edges_ms > 0.0) {
        std::fprintf(out, "edges pass: %.1fx the cost for %.0fx the triangles\n",
                     series.points.back().edges_ms / series.points.front().edges_ms,
                     static_cast<double>(series.points.back().triangles) /
                         static_cast<double>(series.points.front().triangles));
    }
}

}  // namespace bz::app
