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
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/headless_gl.h"
#include "app/line_method_profile.h"
#include "cli/bench_args.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/io/output_path.h"
#include "core/text/printable.h"
#include "level/loader.h"
#include "render/clear_image.h"
#include "scene/camera_check.h"
#include "scene/presentation_clock.h"

namespace bz::app {

namespace {

// summary.json's colour_clears: the path the frames' clears took and, where auto timed both
// paths on this GPU, the times (render/clear_image.h).
Json colour_clears_json(render::Renderer& r) {
    Json j;
    j["path"] = r.colour_clears_by_compute() ? "compute" : "pipeline";
    if (const std::optional<render::ClearTiming> t = r.colour_clear_timing())
        j["measured_ms"] = {{"pipeline", t->pipeline_ms}, {"compute", t->compute_ms}};
    return j;
}

// summary.json's bloom_chain: how the last frame's mip chain went past level 0, drawn level
// by level or walked in one dispatch (render/beam/pass_bloom.cpp); null without a mip chain.
Json bloom_chain_json(const render::Renderer& r) {
    const render::BloomChainSplit split = r.stats().bloom_chain;
    if (split.drawn + split.walked == 0) return nullptr;
    return {{"levels_drawn", split.drawn}, {"levels_walked", split.walked}};
}

namespace fs = std::filesystem;

// Every file this run reads, which no output may replace.
std::vector<fs::path> bench_inputs(const BenchOptions& o) {
    std::vector<fs::path> in;
    if (!o.level.empty()) in.emplace_back(o.level);
    if (!o.replay.empty()) in.emplace_back(o.replay);
    for (const std::string& m : o.models) in.push_back(fs::path(o.models_dir) / m);
    return in;
}

gl::TimingMethod pick_timing(const std::string& wanted, const platform::GlContext& ctx) {
    if (wanted == "cpu") return gl::TimingMethod::cpu_finish;
    if (wanted == "gpu") return gl::TimingMethod::gpu_queries;
    // llvmpipe's GL_TIME_ELAPSED leaves out vertex and geometry work.
    return ctx.is_software() ? gl::TimingMethod::cpu_finish : gl::TimingMethod::gpu_queries;
}

BenchFrames simulate(BenchScene& scene, const BenchOptions& o, double aspect) {
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
        throw UserError(printable(o.replay) + ": the replay has " +
                        std::to_string(bf.frames.size()) + " ticks, not more than the " +
                        std::to_string(o.warmup) + " warm-up frames");
    }
    return bf;
}

void write_text(const fs::path& p, const std::string& s) {
    write_file_atomic(p, s);
}

int run_accuracy_mode(const BenchOptions& o) {
    std::error_code ec;
    fs::create_directory(o.out, ec);  // the folder itself, never missing parents
    if (ec)
        throw UserError(printable(o.out) + ": cannot create the output directory: " + ec.message());
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

int run(const BenchOptions& o) {
    // Every file the run may write sits in --out or these subfolders of it: all are checked
    // before the first frame, so a long run never ends in a refused write.
    constexpr std::string_view kSubfolders[] = {"masks", "diffs", "reference-cache"};
    check_output_dir("--out", o.out, bench_inputs(o), kSubfolders, o.overwrite);
    if (o.mode == BenchMode::accuracy) return run_accuracy_mode(o);
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
    settings.material_lines = loaded.level->render.material_lines.value_or(false);
    settings.intersection_lines = loaded.level->render.intersection_lines.value_or(false);
    const std::string beam_name =
        !o.beam.empty() ? o.beam
                        : loaded.level->render.beam.value_or(std::string(render::kDefaultBeamLook));
    settings.beam = render::beam_look(beam_name);
    // The phosphor's cost is the difference between two runs of the same frames.
    if (o.no_phosphor) settings.beam.phosphor = render::PhosphorDecay::off;
    if (o.colour_clears) settings.colour_clears = *o.colour_clears;
    if (o.prepass_raster) settings.prepass_raster = *o.prepass_raster;
    if (o.bloom_chain) settings.bloom_chain = *o.bloom_chain;
    if (o.edge_prefilter) settings.edge_prefilter = *o.edge_prefilter;
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
    if (ec)
        throw UserError(printable(o.out) + ": cannot create the output directory: " + ec.message());

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
    if (o.mode == BenchMode::sweep) {
        SweepOptions so;
        so.samples = o.samples;
        so.masks_dir = out / "masks";
        fs::create_directory(so.masks_dir, ec);
        if (ec) throw UserError(so.masks_dir.string() + ": cannot create: " + ec.message());
        so.rounds = o.rounds;
        so.auto_compute_from_triangles = profile.threshold();
        so.material_lines = settings.material_lines;
        so.intersection_lines = settings.intersection_lines;
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
    } else if (o.mode == BenchMode::scaling) {
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
        meta.colour_clears = colour_clears_json(renderer);
        meta.bloom_chain = bloom_chain_json(renderer);
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
    const std::optional<BenchOptions> o =
        parse_command("bench", args, kBenchUsage, parse_bench_args, &exit_code);
    return o ? run(*o) : exit_code;
}

}  // namespace bz::app
