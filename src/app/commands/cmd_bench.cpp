// beamzone bench LEVEL: frame-time benchmark along the level's camera path (or a replay),
// offscreen, at a fixed simulated step; --sweep adds the speed-accuracy trade-off against the
// exact CPU reference, --scaling the cost per triangle.
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/bench/bench_accuracy.h"
#include "app/bench/bench_plots.h"
#include "app/bench/bench_report.h"
#include "app/bench/bench_run.h"
#include "app/bench/bench_scaling.h"
#include "app/bench/bench_scene.h"
#include "app/bench/bench_sweep.h"
#include "app/commands/cli_args.h"
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/headless_gl.h"
#include "app/line_method_profile.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/io/output_path.h"
#include "core/text/printable.h"
#include "level/loader.h"
#include "scene/camera_check.h"
#include "scene/presentation_clock.h"

namespace bz::app {

namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: beamzone bench LEVEL [--frames N] [--warmup N] [--size WxH]\n"
    "                      [--preset fast|balanced|high] [--style NAME] [--sweep | --scaling]\n"
    "                      [--line-method compute|geometry_shader|auto|image_outline]\n"
    "                      [--out DIR] [--replay FILE] [--samples N] [--rounds N]\n"
    "                      [--timing auto|cpu|gpu] [--beam classic|mame] [--no-phosphor]\n"
    "                      [--series-max TRIANGLES] [--overwrite]\n"
    "       beamzone bench --accuracy [--models-dir DIR] [--model FILE]... [--size WxH]\n"
    "                      [--frames N] [--out DIR] [--timing auto|cpu|gpu]\n"
    "Renders the level offscreen along its benchmark camera path ([[camera_key]]; without one\n"
    "the autopilot's own view), one simulation tick (1/60 s) per frame, so every machine draws\n"
    "the same frames. --replay FILE plays a recorded game instead, seen by the player.\n"
    "Warm-up frames (default 30) are drawn but not counted; --frames (default 300) are timed.\n"
    "Every pass is timed by name: GL timer queries on a hardware GPU, glFinish + CPU clock on a\n"
    "software rasteriser (--timing overrides). Writes to --out (default bench-out):\n"
    "  summary.json  frame-time mean/p50/p95/p99/max, 1% low FPS, per-pass means, scene stats\n"
    "  frames.csv    one row per frame (MsBetweenPresents, MsCPUBusy, MsPass_<pass>, stats)\n"
    "  frametime.png frame time per frame, stacked by pass\n"
    "--sweep runs every preset, the image-space outline baseline and balanced with culling,\n"
    "LOD and instancing off on the same frames, scores --samples frames (default 6) against\n"
    "the exact CPU reference (F1 at 1 px) and adds sweep.json, tradeoff.png and masks/\n"
    "(default 240 frames per configuration); it then times every style (balanced preset) and\n"
    "scores the sketch style's strokes at 1, 2 and 4 px as well.\n"
    "--style draws every frame in that style (see `render --help` for the styles)\n"
    "instead of the level's.\n"
    "Its timed frames run in --rounds stretches (default 4), round-robin over the\n"
    "configurations, so a machine whose load drifts treats them alike.\n"
    "--scaling draws the frames from meshes subdivided to 1x, 4x, 16x and 64x the triangles\n"
    "and writes scaling.json and scaling.png (default 40 frames), then draws one model (a\n"
    "sphere) at about 20k, 80k, 320k and 1.3M triangles and prints the edges pass against the\n"
    "silhouette it finds (--series-max leaves out the larger sizes; 0 none).\n"
    "--beam picks the vector beam's look (default: the level's, else mame, as play and render);\n"
    "the sweep's rows keep each preset's classic beam and add balanced with the mame beam,\n"
    "which times its passes (phosphor, mip-chain bloom).\n"
    "--no-phosphor switches the beam's phosphor persistence off for the run (not with --sweep):\n"
    "two runs with and without it time what the phosphor costs.\n"
    "--accuracy needs no LEVEL: it scores every preset and the baseline on real models\n"
    "(default: 16 files under /usr/share/assimp/models; --model FILE, repeatable, relative to\n"
    "--models-dir, replaces the list) from 4 views each (framed, behind, close, above) at\n"
    "640x480 against the exact CPU reference (F1 at 1 px Chebyshev), times each view\n"
    "(--frames, default 6) and writes accuracy.json, accuracy_tradeoff.png, masks/, diffs/\n"
    "(red: drawn but hidden in the reference, cyan: missing) and reference-cache/ (exact\n"
    "masks reused by later runs into the same --out).\n"
    "Before the first frame every .json, .csv and .png file already in --out (and its masks/,\n"
    "diffs/, reference-cache/) must be of that kind, and none may be an input of the run;\n"
    "--overwrite lets files of another kind be replaced (never inputs, devices or folders).\n";

enum class Mode { single, sweep, scaling, accuracy };

struct Options {
    std::string level;
    int frames = 300;
    bool frames_given = false;
    int warmup = 30;
    glm::ivec2 size{1280, 720};
    std::string preset;
    std::optional<scene::Style> style;  // none: each frame's own (the level's)
    std::string line_method;            // empty: the level's, else the preset's
    Mode mode = Mode::single;
    std::string out = "bench-out";
    std::string replay;
    int samples = 6;
    int rounds = 4;
    int series_max = 1'400'000;  // --scaling's model series: sizes up to this many triangles
    std::string timing = "auto";
    std::string beam;
    bool no_phosphor = false;
    bool size_given = false;
    std::string models_dir = "/usr/share/assimp/models";
    std::vector<std::string> models;
    bool overwrite = false;  // may replace files of another kind named like an output
};

// Every file this run reads, which no output may replace.
std::vector<fs::path> bench_inputs(const Options& o) {
    std::vector<fs::path> in;
    if (!o.level.empty()) in.emplace_back(o.level);
    if (!o.replay.empty()) in.emplace_back(o.replay);
    for (const std::string& m : o.models) in.push_back(fs::path(o.models_dir) / m);
    return in;
}

Options parse(Args args) {
    Options o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    bool preset_given = false;
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (a == "--frames") {
            o.frames = parse_int(a, cur.value(a), 1, 1000000);
            o.frames_given = true;
        } else if (a == "--warmup") {
            o.warmup = parse_int(a, cur.value(a), 0, 100000);
        } else if (a == "--size") {
            o.size = parse_size(a, cur.value(a));
            o.size_given = true;
        } else if (a == "--preset") {
            o.preset = cur.value(a);
            preset_given = true;
        } else if (a == "--style") {
            o.style = parse_style(a, cur.value(a));
        } else if (a == "--line-method") {
            o.line_method = cur.value(a);
        } else if (a == "--sweep" || a == "--scaling" || a == "--accuracy") {
            const Mode m = a == "--sweep"     ? Mode::sweep
                           : a == "--scaling" ? Mode::scaling
                                              : Mode::accuracy;
            if (o.mode != Mode::single && o.mode != m)
                throw UsageError("--sweep, --scaling and --accuracy exclude each other");
            o.mode = m;
        } else if (a == "--beam") {
            o.beam = cur.value(a);
        } else if (a == "--no-phosphor") {
            o.no_phosphor = true;
        } else if (a == "--models-dir") {
            o.models_dir = cur.value(a);
        } else if (a == "--model") {
            o.models.emplace_back(cur.value(a));
        } else if (a == "--out") {
            o.out = cur.value(a);
        } else if (a == "--overwrite") {
            o.overwrite = true;
        } else if (a == "--replay") {
            o.replay = cur.value(a);
        } else if (a == "--samples") {
            o.samples = parse_int(a, cur.value(a), 1, 1000);
        } else if (a == "--series-max") {
            o.series_max = parse_int(a, cur.value(a), 0, 100'000'000);
        } else if (a == "--rounds") {
            o.rounds = parse_int(a, cur.value(a), 1, 1000);
        } else if (a == "--timing") {
            o.timing = cur.value(a);
            if (o.timing != "auto" && o.timing != "cpu" && o.timing != "gpu") {
                throw UsageError("--timing: expected auto, cpu or gpu");
            }
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else if (o.level.empty()) {
            o.level = a;
        } else {
            throw UsageError("more than one LEVEL given");
        }
    }
    if (o.mode == Mode::accuracy) {
        if (!o.level.empty()) throw UsageError("--accuracy takes no LEVEL (it draws models)");
        if (preset_given) throw UsageError("--preset and --accuracy exclude each other");
        if (!o.replay.empty()) throw UsageError("--replay and --accuracy exclude each other");
        if (o.no_phosphor) throw UsageError("--no-phosphor and --accuracy exclude each other");
        if (!o.frames_given) o.frames = 6;
        if (!o.size_given) o.size = {640, 480};
        if (o.out.empty()) throw UsageError("--out needs a directory");
        return o;
    }
    if (!o.models.empty()) throw UsageError("--model needs --accuracy");
    if (o.level.empty()) throw UsageError("no LEVEL given");
    if (preset_given && o.mode == Mode::sweep)
        throw UsageError("--preset and --sweep exclude each other (the sweep runs every preset)");
    if (!o.line_method.empty() && o.mode == Mode::sweep)
        throw UsageError(
            "--line-method and --sweep exclude each other (the sweep runs every method)");
    if (o.style && o.mode == Mode::sweep)
        throw UsageError("--style and --sweep exclude each other (the sweep runs every style)");
    if (o.no_phosphor && o.mode == Mode::sweep)
        throw UsageError(
            "--no-phosphor and --sweep exclude each other (the sweep sets every look)");
    if (o.mode == Mode::scaling && !o.frames_given) o.frames = 40;
    // Seven configurations: fewer frames each keep a sweep on llvmpipe within minutes.
    if (o.mode == Mode::sweep && !o.frames_given) o.frames = 240;
    if (o.out.empty()) throw UsageError("--out needs a directory");
    return o;
}

gl::TimingMethod pick_timing(const std::string& wanted, const platform::GlContext& ctx) {
    if (wanted == "cpu") return gl::TimingMethod::cpu_finish;
    if (wanted == "gpu") return gl::TimingMethod::gpu_queries;
    // llvmpipe's GL_TIME_ELAPSED leaves out vertex and geometry work.
    return ctx.is_software() ? gl::TimingMethod::cpu_finish : gl::TimingMethod::gpu_queries;
}

BenchFrames simulate(BenchScene& scene, const Options& o, double aspect) {
    BenchFrames bf;
    bf.warmup = o.warmup;
    const int total = o.warmup + o.frames;
    bf.frames.reserve(static_cast<std::size_t>(total));
    scene::FrameList f;
    scene::PresentationClock clock;  // one nominal 60 Hz frame per simulated tick
    for (int i = 0; i < total; ++i) {
        if (!scene.next(f, aspect)) break;
        if (const std::string why = scene::camera_problem(f.camera); !why.empty()) {
            char at[32];
            std::snprintf(at, sizeof at, "%.3f", scene.seconds());
            throw UserError(printable(o.level) + ": at " + at +
                            " s the camera cannot make a picture: " + why);
        }
        clock.advance_nominal();
        clock.stamp(f);
        bf.frames.push_back(f);
        bf.seconds.push_back(scene.seconds());
    }
    if (static_cast<int>(bf.frames.size()) < total &&
        static_cast<int>(bf.frames.size()) > o.warmup) {
        std::fprintf(stderr, "note: %s ends after %zu ticks: timing %zu frames, not %d\n",
                     o.replay.c_str(), bf.frames.size(),
                     bf.frames.size() - static_cast<std::size_t>(o.warmup), o.frames);
    }
    if (static_cast<int>(bf.frames.size()) <= o.warmup) {
        throw UserError(o.replay + ": the replay has " + std::to_string(bf.frames.size()) +
                        " ticks, not more than the " + std::to_string(o.warmup) +
                        " warm-up frames");
    }
    return bf;
}

void write_text(const fs::path& p, const std::string& s) {
    write_file_atomic(p, s);
}

int run_accuracy_mode(const Options& o) {
    std::error_code ec;
    fs::create_directory(o.out, ec);  // the folder itself, never missing parents
    if (ec) throw UserError(o.out + ": cannot create the output directory: " + ec.message());
    auto context = make_headless_context();
    check_image_size(*context, "--size", o.size.x, o.size.y);
    const gl::TimingMethod timing = pick_timing(o.timing, *context);
    const LineMethodProfile profile = user_line_method_profile(Calibration::measure_if_missing);
    std::unique_ptr<scene::VectorFont> font;
    try {
        font = std::make_unique<scene::VectorFont>(scene::VectorFont::load_default());
    } catch (const UserError& e) {
        std::fprintf(stderr, "beamzone bench: warning: plots without labels: %s\n", e.what());
    }
    AccuracyOptions ao;
    ao.models_dir = o.models_dir;
    for (const std::string& m : o.models) ao.models.push_back({m, "given with --model"});
    ao.width = o.size.x;
    ao.height = o.size.y;
    ao.frames = o.frames;
    ao.warmup = std::min(o.warmup, 1);
    ao.out = o.out;
    ao.auto_compute_from_triangles = profile.threshold();
    BenchMeta meta;
    meta.level = "real models (" + o.models_dir + ")";
    meta.camera = "framed, behind, close, above per model";
    meta.width = o.size.x;
    meta.height = o.size.y;
    meta.frames = o.frames;
    meta.warmup = ao.warmup;
    meta.gl_renderer = context->renderer_name();
    meta.software = context->is_software();
    meta.timing = timing;
    meta.auto_line_method = line_method_profile_json(profile);
    meta.load_before = load_average();
    const AccuracyResult result = run_accuracy(ao, timing);
    meta.load_after = load_average();
    if (result.views.empty()) throw UserError("accuracy: no model could be loaded");
    const std::vector<Goal> goals = judge_accuracy_goals(result);
    const fs::path out(o.out);
    write_text(out / "accuracy.json", accuracy_json(meta, ao, result, goals));
    std::vector<TradeoffPoint> points;
    for (const AccuracyRow& r : result.rows)
        points.push_back({r.config.label, r.mean_p50_ms, r.mean_f1, r.min_f1});
    plot_tradeoff(
        points,
        "speed vs accuracy, " + std::to_string(result.views.size()) + " views of real models",
        font.get(), out / "accuracy_tradeoff.png");
    print_accuracy_table(stdout, result, goals, ao.tolerance_px);
    std::printf("load average %.2f before, %.2f after\nwrote %s/\n", meta.load_before,
                meta.load_after, o.out.c_str());
    if (context->debug().error_count() > 0) {
        std::fprintf(stderr, "beamzone bench: %d OpenGL error(s) reported\n",
                     context->debug().error_count());
        return 1;
    }
    return 0;
}

int run(const Options& o) {
    // Every file the run may write sits in --out or these subfolders of it: all are checked
    // before the first frame, so a long run never ends in a refused write.
    constexpr std::string_view kSubfolders[] = {"masks", "diffs", "reference-cache"};
    check_output_dir("--out", o.out, bench_inputs(o), kSubfolders, o.overwrite);
    if (o.mode == Mode::accuracy) return run_accuracy_mode(o);
    level::LoadResult loaded = level::load_level_file(o.level);
    if (!loaded.ok()) {
        for (const level::Diagnostic& d : loaded.errors)
            std::fprintf(stderr, "%s\n", level::format(d).c_str());
        return 1;
    }
    const std::string preset_name = o.preset.empty() ? loaded.level->render.preset : o.preset;
    render::RenderSettings settings =
        render::preset(preset_name.empty() ? "balanced" : preset_name);
    if (!o.line_method.empty())
        settings.method = render::parse_line_method(o.line_method);
    else if (loaded.level->render.line_method)
        settings.method = render::parse_line_method(*loaded.level->render.line_method);
    settings.count_edges = true;
    const std::string beam_name =
        !o.beam.empty() ? o.beam
                        : loaded.level->render.beam.value_or(std::string(render::kDefaultBeamLook));
    settings.beam = render::beam_look(beam_name);
    // The phosphor's cost is the difference between two runs of the same frames.
    if (o.no_phosphor) settings.beam.phosphor = render::PhosphorDecay::off;
    settings.style = o.style;
    std::optional<game::replay::Replay> replay;
    if (!o.replay.empty()) replay = game::replay::load(o.replay);

    const double aspect = static_cast<double>(o.size.x) / o.size.y;
    BenchScene scene(std::move(*loaded.level), std::move(replay));
    std::fprintf(stderr, "simulating %d frames of %s ...\n", o.warmup + o.frames, o.level.c_str());
    const BenchFrames frames = simulate(scene, o, aspect);
    scene.prove_replay();
    if (const auto& m = scene.replay_mismatch()) {
        // As `play --replay`: a replay that diverged is an error, and its frames are not the
        // recorded game, so nothing is timed.
        std::fprintf(stderr,
                     "beamzone bench: error: %s: replay diverged at tick %llu (state hash %016llx, "
                     "recorded %016llx); nothing was timed\n",
                     printable(o.replay).c_str(), static_cast<unsigned long long>(m->tick),
                     static_cast<unsigned long long>(m->actual),
                     static_cast<unsigned long long>(m->expected));
        return 1;
    }

    std::error_code ec;
    fs::create_directory(o.out, ec);  // the folder itself, never missing parents
    if (ec) throw UserError(o.out + ": cannot create the output directory: " + ec.message());

    auto context = make_headless_context();
    check_image_size(*context, "--size", o.size.x, o.size.y);
    const gl::TimingMethod timing = pick_timing(o.timing, *context);
    const LineMethodProfile profile = user_line_method_profile(Calibration::measure_if_missing);
    settings.auto_compute_from_triangles = profile.threshold();
    const scene::VectorFont* font = nullptr;
    std::unique_ptr<scene::VectorFont> font_storage;
    try {
        font_storage = std::make_unique<scene::VectorFont>(scene::VectorFont::load_default());
        font = font_storage.get();
    } catch (const UserError& e) {
        std::fprintf(stderr, "beamzone bench: warning: plots without labels: %s\n", e.what());
    }

    BenchMeta meta;
    meta.level = o.level;
    meta.camera = scene.camera_description();
    meta.width = o.size.x;
    meta.height = o.size.y;
    meta.frames = static_cast<int>(frames.frames.size()) - frames.warmup;
    meta.warmup = frames.warmup;
    meta.gl_renderer = context->renderer_name();
    meta.software = context->is_software();
    meta.timing = timing;
    meta.auto_line_method = line_method_profile_json(profile);
    meta.load_before = load_average();
    const fs::path out(o.out);

    std::vector<RunResult> runs;
    if (o.mode == Mode::sweep) {
        SweepOptions so;
        so.samples = o.samples;
        so.masks_dir = out / "masks";
        fs::create_directory(so.masks_dir, ec);
        if (ec) throw UserError(so.masks_dir.string() + ": cannot create: " + ec.message());
        so.rounds = o.rounds;
        so.auto_compute_from_triangles = profile.threshold();
        const SweepResult result =
            run_sweep(frames, scene.meshes(), o.size.x, o.size.y, timing, so);
        meta.load_after = load_average();
        const std::vector<Goal> goals = judge_goals(result.rows);
        std::vector<TradeoffPoint> points;
        for (const SweepRow& r : result.rows) {
            runs.push_back(r.run);
            points.push_back({r.config.label, r.run.stats.p50_ms, r.score.mean_f1, r.score.min_f1});
            plot_frame_times(r.run, r.config.label + ": frame time by pass", font,
                             out / ("frametime_" + r.config.label + ".png"));
        }
        write_text(out / "sweep.json", sweep_json(meta, result, goals));
        plot_tradeoff(points, "speed vs accuracy, " + fs::path(o.level).filename().string(), font,
                      out / "tradeoff.png");
        for (const SweepRow& r : result.rows) {
            if (r.config.label == "balanced")
                plot_frame_times(r.run, "balanced: frame time by pass", font,
                                 out / "frametime.png");
        }
        print_summary_table(stdout, meta, runs);
        print_sweep_table(stdout, result, goals);
    } else if (o.mode == Mode::scaling) {
        ScalingResult result = run_scaling(frames, scene.meshes(), settings, o.size.x, o.size.y,
                                           timing, 60'000'000, true);
        result.series = run_model_series(settings, o.size.x, o.size.y, timing,
                                         std::min(o.frames, 10), o.series_max, true);
        meta.load_after = load_average();
        runs = result.runs;
        write_text(out / "scaling.json", scaling_json(meta, result));
        plot_scaling(result.points, result.fit,
                     "frame time against triangles, " + fs::path(o.level).filename().string(), font,
                     out / "scaling.png");
        if (!runs.empty())
            plot_frame_times(runs.front(), "1x: frame time by pass", font, out / "frametime.png");
        print_summary_table(stdout, meta, runs);
        std::printf(
            "growth: %.2f ms per 100k triangles submitted (fit intercept %.2f ms, r2 %.3f)\n",
            result.fit.slope * 1e5, result.fit.intercept, result.fit.r2);
        for (const std::string& s : result.skipped) std::printf("skipped %s\n", s.c_str());
        std::printf("%-8s %12s %14s\n", "factor", "edges pass ms", "feature edges");
        for (std::size_t i = 0; i < result.points.size(); ++i) {
            std::printf("%-8s %12.2f %14.0f\n", result.points[i].label.c_str(),
                        mean_pass_ms(result.runs[i], "edges"), mean_feature_edges(result.runs[i]));
        }
        print_model_series(stdout, result.series);
    } else {
        render::Renderer renderer(settings, o.size.x, o.size.y, timing);
        ProgressBar bar(settings.preset, meta.frames);
        runs.push_back(run_frames(renderer, frames, scene.meshes(), settings.preset, settings,
                                  [&bar] { bar(); }));
        meta.load_after = load_average();
        plot_frame_times(runs.front(), settings.preset + ": frame time by pass", font,
                         out / "frametime.png");
        print_summary_table(stdout, meta, runs);
    }
    write_text(out / "summary.json", summary_json(meta, runs));
    write_text(out / "frames.csv", frames_csv(runs));
    std::printf("wrote %s/\n", o.out.c_str());
    if (context->debug().error_count() > 0) {
        std::fprintf(stderr, "beamzone bench: %d OpenGL error(s) reported\n",
                     context->debug().error_count());
        return 1;
    }
    return 0;
}

}  // namespace

int cmd_bench(Args args) {
    int exit_code = 0;
    const auto parse_checked = [](Args a) {
        Options o = parse(a);
        try {
            if (!o.preset.empty()) render::preset(o.preset);  // an unknown name is a usage error
            if (!o.line_method.empty()) render::parse_line_method(o.line_method);
            if (!o.beam.empty()) render::beam_look(o.beam);
        } catch (const UserError& e) {
            throw UsageError(e.what());
        }
        return o;
    };
    const std::optional<Options> o =
        parse_command("bench", args, kUsage, parse_checked, &exit_code);
    return o ? run(*o) : exit_code;
}

}  // namespace bz::app
