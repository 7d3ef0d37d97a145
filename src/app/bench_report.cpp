#include "app/bench_report.h"

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

void write_meta(JsonWriter& j, const BenchMeta& m) {
    j.field("beamzone_version", BEAMZONE_VERSION);
    j.field("level", m.level);
    j.field("camera", m.camera);
    j.key("size").begin_array().value(m.width).value(m.height).end_array();
    j.field("frames", m.frames);
    j.field("warmup_frames", m.warmup);
    j.field("simulated_step_s", 1.0 / 60.0);
    j.field("gl_renderer", m.gl_renderer);
    j.field("software_rasteriser", m.software);
    j.field("timing_method", timing_name(m.timing));
    j.field("timing_note", timing_note(m.timing));
    j.field("load_average_before", m.load_before);
    j.field("load_average_after", m.load_after);
}

void write_run(JsonWriter& j, const RunResult& r) {
    const render::RenderSettings& s = r.settings;
    j.field("label", r.label);
    j.key("settings").begin_object();
    j.field("preset", s.preset);
    j.field("method", s.method == render::LineMethod::geometry ? "geometry" : "image_outline");
    j.field("depth", depth_name(s.depth));
    j.field("spine_samples", s.spine_samples);
    j.field("plane_tolerance_rel", static_cast<double>(s.plane_tolerance_rel));
    j.field("plane_tolerance_px", static_cast<double>(s.plane_tolerance_px));
    j.field("depth_bias", static_cast<double>(s.depth_bias));
    j.field("line_half_width_px", static_cast<double>(s.line_half_width_px));
    j.field("crease_angle_deg", static_cast<double>(s.crease_angle_deg));
    j.field("bloom_resolution_divisor", static_cast<int>(s.bloom_resolution));
    j.field("bloom_taps", s.bloom_taps);
    j.field("frustum_culling", s.frustum_culling);
    j.field("lod", s.lod);
    j.field("instancing", s.instancing);
    j.end_object();
    const FrameTimeStats& t = r.stats;
    j.key("frame_time_ms").begin_object();
    j.field("mean", t.mean_ms).field("p50", t.p50_ms).field("p95", t.p95_ms).field("p99", t.p99_ms);
    j.field("max", t.max_ms).field("min", t.min_ms);
    j.end_object();
    j.key("fps")
        .begin_object()
        .field("mean", t.mean_fps)
        .field("low_1pct", t.low_1pct_fps)
        .end_object();
    j.field("cpu_busy_mean_ms",
            mean_of(r.frames, [](const FrameRecord& f) { return f.ms_cpu_busy; }));
    j.key("passes_mean_ms").begin_object();
    for (std::size_t p = 0; p < r.pass_names.size(); ++p)
        j.field(r.pass_names[p], mean_pass_ms(r, p));
    j.end_object();
    j.key("scene_per_frame").begin_object();
    j.field("objects_drawn_mean",
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.objects_drawn; }));
    j.field("objects_culled_mean",
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.objects_culled; }));
    j.field("triangles_submitted_mean",
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.triangles_submitted; }));
    j.field("triangles_submitted_max",
            max_of(r.frames, [](const FrameRecord& f) { return f.stats.triangles_submitted; }));
    j.field("feature_edges_mean",
            mean_of(r.frames, [](const FrameRecord& f) { return f.stats.feature_edges; }));
    j.field("feature_edges_max",
            max_of(r.frames, [](const FrameRecord& f) { return f.stats.feature_edges; }));
    j.end_object();
}

std::string summary_json(const BenchMeta& meta, const std::vector<RunResult>& runs) {
    JsonWriter j;
    j.begin_object();
    write_meta(j, meta);
    j.key("runs").begin_array();
    for (const RunResult& r : runs) {
        j.begin_object();
        write_run(j, r);
        j.end_object();
    }
    j.end_array();
    j.end_object();
    return j.str();
}

void print_summary_table(std::FILE* out, const BenchMeta& m, const std::vector<RunResult>& runs) {
    std::fprintf(out, "\n%s, %dx%d, %d frames (+%d warm-up) at 1/60 s, %s\n", m.level.c_str(),
                 m.width, m.height, m.frames, m.warmup, m.camera.c_str());
    std::fprintf(out, "%s on %s; load average %.2f -> %.2f\n", timing_name(m.timing),
                 m.gl_renderer.c_str(), m.load_before, m.load_after);
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
        std::fprintf(out, " | objects %.0f drawn %.0f culled, %.0f feature edges\n", drawn, culled,
                     edges);
    }
}

}  // namespace bz::app
