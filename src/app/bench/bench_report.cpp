#include "app/bench/bench_report.h"

#include <algorithm>
#include <fstream>
#include <numeric>
#include <sstream>

namespace bz::app {

namespace {

template <class F>
double mean_of(const std::vector<FrameRecord>& frames, F get) {
    if (frames.empty()) return 0.0;
    double s = 0.0;
    for (const FrameRecord& f : frames) s += static_cast<double>(get(f));
    return s / static_cast<double>(frames.size());
}

template <class F>
double max_of(const std::vector<FrameRecord>& frames, F get) {
    double m = 0.0;
    for (const FrameRecord& f : frames) m = std::max(m, static_cast<double>(get(f)));
    return m;
}

double whole_image_downsample_share(const RunResult& r) {
    return mean_of(r.frames, [](const FrameRecord& f) {
        return f.stats.first_downsample == render::FirstDownsampleRead::whole_image ? 1 : 0;
    });
}

const char* depth_name(render::DepthFormat d) {
    return d == render::DepthFormat::reversed_f32 ? "reversed_f32" : "conventional_d24";
}

}  // namespace

const char* timing_name(gl::TimingMethod m) {
    switch (m) {
        case gl::TimingMethod::cpu_finish:
            return "cpu_finish";
        case gl::TimingMethod::gpu_queries:
            return "gpu_queries";
        case gl::TimingMethod::off:
            break;
    }
    return "off";
}

const char* timing_note(gl::TimingMethod m) {
    switch (m) {
        case gl::TimingMethod::cpu_finish:
            return "passes timed with glFinish + CPU clock (software rasteriser: timer queries "
                   "miss its "
                   "vertex and geometry work)";
        case gl::TimingMethod::gpu_queries:
            return "passes timed with GL_TIME_ELAPSED queries, read back a few frames late";
        case gl::TimingMethod::off:
            break;
    }
    return "passes not timed";
}

double load_average() {
    std::ifstream in("/proc/loadavg");
    double v = -1.0;
    if (!(in >> v)) return -1.0;
    return v;
}

double mean_pass_ms(const RunResult& run, std::size_t pass) {
    double s = 0.0;
    std::size_t n = 0;
    for (const FrameRecord& f : run.frames) {
        if (pass < f.pass_ms.size() && f.pass_ms[pass] >= 0.0) {
            s += f.pass_ms[pass];
            ++n;
        }
    }
    return n ? s / static_cast<double>(n) : 0.0;
}

std::string frames_csv(const std::vector<RunResult>& runs) {
    // One header for all runs: the union of their pass names.
    std::vector<std::string> passes;
    for (const RunResult& r : runs) {
        for (const std::string& p : r.pass_names) {
            if (std::find(passes.begin(), passes.end(), p) == passes.end()) passes.push_back(p);
        }
    }
    std::ostringstream out;
    out.precision(6);
    out << std::fixed;
    out << "Config,Frame,TimeInSeconds,MsBetweenPresents,MsCPUBusy";
    for (const std::string& p : passes) out << ",MsPass_" << p;
    out << ",ObjectsDrawn,ObjectsCulled,TrianglesSubmitted,FeatureEdges\n";
    for (const RunResult& r : runs) {
        for (const FrameRecord& f : r.frames) {
            out << r.label << ',' << f.frame << ',' << f.seconds << ',' << f.ms_between << ','
                << f.ms_cpu_busy;
            for (const std::string& p : passes) {
                const auto it = std::find(r.pass_names.begin(), r.pass_names.end(), p);
                const auto i = static_cast<std::size_t>(it - r.pass_names.begin());
                out << ',';
                if (it != r.pass_names.end() && i < f.pass_ms.size() && f.pass_ms[i] >= 0.0)
                    out << f.pass_ms[i];
            }
            out << ',' << f.stats.objects_drawn << ',' << f.stats.objects_culled << ','
                << f.stats.triangles_submitted << ',' << f.stats.feature_edges << '\n';
        }
    }
    return out.str();
}

Json meta_json(const BenchMeta& m) {
    Json j = Json::object();
    j["beamzone_version"] = BEAMZONE_VERSION;
    j["level"] = m.level;
    j["camera"] = m.camera;
    j["size"] = Json::array({m.width, m.height});
    j["frames"] = m.frames;
    j["warmup_frames"] = m.warmup;
    j["simulated_step_s"] = 1.0 / 60.0;
    j["gl_renderer"] = m.gl_renderer;
    j["software_rasteriser"] = m.software;
    j["timing_method"] = timing_name(m.timing);
    j["timing_note"] = timing_note(m.timing);
    j["load_average_before"] = m.load_before;
    j["load_average_after"] = m.load_after;
    j["auto_line_method"] = m.auto_line_method;
    if (!m.colour_clears.is_null()) j["colour_clears"] = m.colour_clears;
    if (!m.bloom_chain.is_null()) j["bloom_chain"] = m.bloom_chain;
    return j;
}

Json run_json(const RunResult& r) {
    const render::RenderSettings& s = r.settings;
    Json j = Json::object();
    j["label"] = r.label;
    Json settings = Json::object();
    settings["preset"] = s.preset;
    settings["method"] = render::line_method_name(s.method);
    settings["depth"] = depth_name(s.depth);
    settings["plane_tolerance_rel"] = static_cast<double>(s.plane_tolerance_rel);
    settings["plane_tolerance_px"] = static_cast<double>(s.plane_tolerance_px);
    settings["depth_bias"] = static_cast<double>(s.depth_bias);
    settings["spine_sample_spacing_px"] = static_cast<double>(s.spine_sample_spacing_px);
    settings["line_half_width_px"] = static_cast<double>(s.line_half_width_px);
    settings["crease_angle_deg"] = static_cast<double>(s.crease_angle_deg);
    settings["bloom_resolution_divisor"] = static_cast<int>(s.bloom_resolution);
    settings["bloom_taps"] = s.bloom_taps;
    settings["frustum_culling"] = s.frustum_culling;
    settings["lod"] = s.lod;
    settings["instancing"] = s.instancing;
    settings["beam"] = s.beam.look;  // classic or mame: the sweep's balanced-mame row
    // bench --no-phosphor switches it off whatever the look.
    settings["phosphor"] = s.beam.phosphor == render::PhosphorDecay::off           ? "off"
                           : s.beam.phosphor == render::PhosphorDecay::exponential ? "exponential"
                                                                                   : "power_law";
    j["settings"] = std::move(settings);
    const FrameTimeStats& t = r.stats;
    j["frame_time_ms"] = Json{{"mean", t.mean_ms}, {"p50", t.p50_ms}, {"p95", t.p95_ms},
                              {"p99", t.p99_ms},   {"max", t.max_ms}, {"min", t.min_ms}};
    j["fps"] = Json{{"mean", t.mean_fps}, {"low_1pct", t.low_1pct_fps}};
    j["cpu_busy_mean_ms"] = mean_of(r.frames, [](const FrameRecord& f) { return f.ms_cpu_busy; });
    Json passes = Json::object();
    for (std::size_t p = 0; p < r.pass_names.size(); ++p)
        passes[r.pass_names[p]] = mean_pass_ms(r, p);
    j["passes_mean_ms"] = std::move(passes);
    Json scene = Json::object();
    scene["objects_drawn_mean"] =
        mean_of(r.frames, [](const FrameRecord& f) { return f.stats.objects_drawn; });
    scene["objects_culled_mean"] =
        mean_of(r.frames, [](const FrameRecord& f) { return f.stats.objects_culled; });
    scene["triangles_submitted_mean"] =
        mean_of(r.frames, [](const FrameRecord& f) { return f.stats.triangles_submitted; });
    scene["triangles_submitted_max"] =
        max_of(r.frames, [](const FrameRecord& f) { return f.stats.triangles_submitted; });
    // Under LineMethod::automatic: the share of frames it drew with the compute method.
    scene["compute_line_method_share"] = mean_of(r.frames, [](const FrameRecord& f) {
        return f.stats.line_method == render::LineMethod::compute ? 1 : 0;
    });
    // RenderSettings::first_downsample: the share of frames whose bloom read the whole beam
    // image rather than the marked tiles (0 without a bloom).
    scene["whole_image_first_downsample_share"] = whole_image_downsample_share(r);
    scene["feature_edges_mean"] =
        mean_of(r.frames, [](const FrameRecord& f) { return f.stats.feature_edges; });
    scene["feature_edges_max"] =
        max_of(r.frames, [](const FrameRecord& f) { return f.stats.feature_edges; });
    // Intersection lines (zero when off): the CPU's update of the cached crossings, the pairs
    // it had to compute (objects that moved into each other) and the segments drawn.
    scene["intersection_update_ms_mean"] =
        mean_of(r.frames, [](const FrameRecord& f) { return f.stats.intersections.update_ms; });
    scene["intersection_update_ms_max"] =
        max_of(r.frames, [](const FrameRecord& f) { return f.stats.intersections.update_ms; });
    scene["intersection_pairs_computed_mean"] = mean_of(
        r.frames, [](const FrameRecord& f) { return f.stats.intersections.pairs_computed; });
    scene["intersection_segments_mean"] =
        mean_of(r.frames, [](const FrameRecord& f) { return f.stats.intersection_records; });
    j["scene_per_frame"] = std::move(scene);
    return j;
}

std::string summary_json(const BenchMeta& meta, const std::vector<RunResult>& runs) {
    Json j = meta_json(meta);
    Json list = Json::array();
    for (const RunResult& r : runs) list.push_back(run_json(r));
    j["runs"] = std::move(list);
    return json_text(j);
}

void print_summary_table(std::FILE* out, const BenchMeta& m, const std::vector<RunResult>& runs) {
    std::fprintf(out, "\n%s, %dx%d, %d frames (+%d warm-up) at 1/60 s, %s\n", m.level.c_str(),
                 m.width, m.height, m.frames, m.warmup, m.camera.c_str());
    std::fprintf(out, "%s on %s; load average %.2f -> %.2f\n", timing_name(m.timing),
                 m.gl_renderer.c_str(), m.load_before, m.load_after);
    const Json& auto_method = m.auto_line_method;
    if (auto_method.is_object() && auto_method.contains("source")) {
        std::string from = "the built-in rule";
        if (auto_method.contains("measurement") && auto_method.at("measurement").is_object()) {
            const Json& f = auto_method.at("measurement").at("compute_from_triangles");
            from = f.is_null() ? "never" : f.dump() + " triangles";
        }
        std::fprintf(out, "auto line method: compute from %s (%s)\n", from.c_str(),
                     auto_method.at("source").get<std::string>().c_str());
    }
    std::fprintf(out, "%-24s %8s %8s %8s %8s %8s %9s %9s\n", "config", "mean ms", "p50", "p95",
                 "p99", "max", "1%low fps", "tris/frm");
    for (const RunResult& r : runs) {
        const FrameTimeStats& t = r.stats;
        const double tris =
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.triangles_submitted; });
        std::fprintf(out, "%-24s %8.2f %8.2f %8.2f %8.2f %8.2f %9.1f %9.0f\n", r.label.c_str(),
                     t.mean_ms, t.p50_ms, t.p95_ms, t.p99_ms, t.max_ms, t.low_1pct_fps, tris);
    }
    for (const RunResult& r : runs) {
        std::fprintf(out, "  %-22s passes (mean ms):", r.label.c_str());
        for (std::size_t p = 0; p < r.pass_names.size(); ++p) {
            std::fprintf(out, " %s %.2f", r.pass_names[p].c_str(), mean_pass_ms(r, p));
        }
        const double drawn =
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.objects_drawn; });
        const double culled =
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.objects_culled; });
        const double edges =
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.feature_edges; });
        std::fprintf(out, " | objects %.0f drawn %.0f culled, %.0f feature edges", drawn, culled,
                     edges);
        if (r.settings.method == render::LineMethod::automatic) {
            const double compute = mean_of(r.frames, [](const FrameRecord& f) {
                return f.stats.line_method == render::LineMethod::compute ? 1 : 0;
            });
            std::fprintf(out, ", auto: compute lines in %.0f%% of frames", 100.0 * compute);
        }
        if (const double whole = whole_image_downsample_share(r); whole > 0.0)
            std::fprintf(out, ", first bloom downsample over the whole image in %.0f%% of frames",
                         100.0 * whole);
        std::fprintf(out, "\n");
    }
}

}  // namespace bz::app
