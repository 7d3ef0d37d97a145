#include "app/bench/bench_sweep.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "app/bench/bench_text.h"
#include "core/image_io.h"
#include "render/reference_frame.h"

namespace bz::app {

namespace {

const SweepRow* find_row(const std::vector<SweepRow>& rows, const std::string& label) {
    for (const SweepRow& r : rows) {
        if (r.config.label == label) return &r;
    }
    return nullptr;
}

SweepScore summarise(std::vector<geo::MaskScore> scores) {
    SweepScore s;
    if (scores.empty()) return s;
    for (const geo::MaskScore& m : scores) {
        s.mean_f1 += m.f1;
        s.mean_precision += m.precision;
        s.mean_recall += m.recall;
        s.min_f1 = std::min(s.min_f1, m.f1);
    }
    const auto n = static_cast<double>(scores.size());
    s.mean_f1 /= n;
    s.mean_precision /= n;
    s.mean_recall /= n;
    s.per_sample = std::move(scores);
    return s;
}

}  // namespace

std::vector<SweepConfig> sweep_configs() {
    std::vector<SweepConfig> out;
    for (const std::string& name : render::preset_names()) {
        out.push_back(
            {name,
             "preset " + name + " (" + render::line_method_name(render::kDefaultLineMethod) + ")",
             render::preset(name)});
    }
    // Each preset again with each line method given outright (the default, auto, picks one of
    // them per frame): same lines, so the same F1, other cost.
    for (const render::LineMethod m : render::feature_line_methods()) {
        if (m == render::kDefaultLineMethod) continue;
        std::string suffix = render::line_method_name(m);
        std::replace(suffix.begin(), suffix.end(), '_', '-');
        for (const std::string& name : render::preset_names()) {
            SweepConfig c{name + "-" + suffix,
                          "preset " + name + ", line method " + render::line_method_name(m),
                          render::preset(name)};
            c.settings.method = m;
            out.push_back(c);
        }
    }
    SweepConfig per_fragment{
        "balanced-per-fragment",
        "balanced, compute line method with the spine test in every line fragment "
        "instead of once per spine sample",
        render::preset("balanced")};
    per_fragment.settings.method = render::LineMethod::compute;
    per_fragment.settings.spine_sample_spacing_px = 0.0f;
    out.push_back(per_fragment);
    SweepConfig outline{"image-outline",
                        "baseline: Sobel on prepass depth + normals, balanced bloom",
                        render::preset("balanced")};
    outline.settings.method = render::LineMethod::image_outline;
    out.push_back(outline);
    SweepConfig no_cull{"balanced-no-culling", "balanced, frustum culling off",
                        render::preset("balanced")};
    no_cull.settings.frustum_culling = false;
    out.push_back(no_cull);
    SweepConfig no_lod{"balanced-no-lod",
                       "balanced, distance LOD off (no simplified meshes, one crease angle)",
                       render::preset("balanced")};
    no_lod.settings.lod = false;
    out.push_back(no_lod);
    SweepConfig no_inst{"balanced-no-instancing",
                        "balanced, one draw call per object instead of per model",
                        render::preset("balanced")};
    no_inst.settings.instancing = false;
    out.push_back(no_inst);
    SweepConfig mame{
        "balanced-mame",
        "balanced with the mame beam: additive, intensity width, phosphor, mip-chain bloom",
        render::preset("balanced")};
    mame.settings.beam = render::beam_look("mame");
    out.push_back(mame);
    // An extra line kind on: one row as balanced draws it, then one per line method given
    // outright: what the kind costs, and that both methods agree with the reference that
    // draws it too.
    const auto add_kind_rows = [&](const std::string& name, const std::string& what,
                                   bool render::RenderSettings::*kind) {
        SweepConfig plain{"balanced-" + name, "balanced with " + what, render::preset("balanced")};
        plain.settings.*kind = true;
        out.push_back(plain);
        for (const render::LineMethod m : render::feature_line_methods()) {
            std::string suffix = render::line_method_name(m);
            std::replace(suffix.begin(), suffix.end(), '_', '-');
            SweepConfig c{"balanced-" + name + "-" + suffix,
                          "balanced with " + name.substr(0, name.find('-')) + " lines on, " +
                              "line method " + render::line_method_name(m),
                          render::preset("balanced")};
            c.settings.*kind = true;
            c.settings.method = m;
            out.push_back(c);
        }
    };
    add_kind_rows("material-lines", "material lines on (edges between materials)",
                  &render::RenderSettings::material_lines);
    add_kind_rows("intersection-lines", "intersection lines on (where surfaces cross)",
                  &render::RenderSettings::intersection_lines);
    // Every style on the same frames (balanced preset): "balanced" is the level's own style,
    // so a level in the vector style needs no row of its own for it.
    for (const scene::Style style : scene::all_styles()) {
        const std::string name(scene::style_name(style));
        SweepConfig c{"style-" + name, "style " + name + ", balanced preset",
                      render::preset("balanced")};
        c.settings.style = style;
        out.push_back(c);
    }
    for (SweepConfig& c : out) c.settings.count_edges = true;
    return out;
}

std::vector<int> sampled_frames(int timed, int samples) {
    std::vector<int> out;
    if (timed <= 0 || samples <= 0) return out;
    samples = std::min(samples, timed);
    for (int i = 0; i < samples; ++i) {
        // Centres of equal stretches, so neither the first nor the last frame dominates.
        out.push_back(static_cast<int>((static_cast<double>(i) + 0.5) * timed / samples));
    }
    return out;
}

SweepResult run_sweep(const BenchFrames& bf, const scene::MeshLibrary& meshes, int width,
                      int height, gl::TimingMethod timing, const SweepOptions& o) {
    SweepResult result;
    const int timed = static_cast<int>(bf.frames.size()) - bf.warmup;
    result.sampled = sampled_frames(timed, o.samples);
    for (int f : result.sampled)
        result.sampled_seconds.push_back(bf.seconds[static_cast<std::size_t>(f + bf.warmup)]);
    auto frame_of = [&](int timed_frame) -> const scene::FrameList& {
        return bf.frames[static_cast<std::size_t>(timed_frame + bf.warmup)];
    };
    auto mask_path = [&](const std::string& label, int frame) {
        char name[96];
        std::snprintf(name, sizeof name, "%s_frame%04d.png", label.c_str(), frame);
        return o.masks_dir / name;
    };

    std::vector<SweepConfig> configs = sweep_configs();
    for (SweepConfig& c : configs) {
        c.settings.material_lines |= o.material_lines;
        c.settings.intersection_lines |= o.intersection_lines;
    }
    // Per sampled frame, the reference for each mix of the extra kinds the rows draw (bit 0:
    // material lines, bit 1: intersection lines); each row is scored against the one that
    // draws what it draws. The scene says whether there are any: a level without
    // multi-material models or crossings gets equal masks.
    const auto kinds_of = [](const SweepConfig& c) {
        return (c.settings.material_lines ? 1 : 0) | (c.settings.intersection_lines ? 2 : 0);
    };
    std::vector<std::vector<std::uint8_t>> refs[4];
    bool wanted[4] = {false, false, false, false};
    for (const SweepConfig& c : configs) wanted[kinds_of(c)] = true;
    const auto t0 = std::chrono::steady_clock::now();
    ProgressBar ref_bar("reference masks (CPU)",
                        static_cast<int>(result.sampled.size()) *
                            static_cast<int>(std::count(wanted, wanted + 4, true)));
    const char* const ref_names[4] = {"reference", "reference-material", "reference-intersection",
                                      "reference-material-intersection"};
    for (int with = 0; with < 4; ++with) {
        if (!wanted[with]) continue;
        render::ReferenceFrameOptions ro;
        ro.material_lines = (with & 1) != 0;
        ro.intersection_lines = (with & 2) != 0;
        for (std::size_t k = 0; k < result.sampled.size(); ++k) {
            geo::ReferenceStats st;
            refs[with].push_back(render::reference_frame_mask(frame_of(result.sampled[k]), meshes,
                                                              width, height, ro, &st));
            result.reference_rays += st.rays;
            if (!o.masks_dir.empty())
                write_png(mask_path(ref_names[with], result.sampled[k]),
                          Image{width, height, 1, refs[with].back()});
            if (o.progress) ref_bar();
        }
    }
    result.reference_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    std::vector<std::unique_ptr<render::Renderer>> renderers;
    std::vector<RunResult> runs;
    for (SweepConfig c : configs) {
        c.settings.auto_compute_from_triangles = o.auto_compute_from_triangles;
        renderers.push_back(std::make_unique<render::Renderer>(c.settings, width, height, timing));
        runs.push_back(start_run(bf, c.label, c.settings));
    }
    ProgressBar bar("sweep (" + std::to_string(configs.size()) + " configs)",
                    timed * static_cast<int>(configs.size()));
    Progress progress;
    if (o.progress) progress = [&bar] { bar(); };
    const int rounds = std::clamp(o.rounds, 1, std::max(timed, 1));
    for (int r = 0; r < rounds; ++r) {
        const int first = timed * r / rounds, last = timed * (r + 1) / rounds;
        for (std::size_t c = 0; c < configs.size(); ++c) {
            // The first stretch of each configuration gets the full warm-up (shader
            // compilation, first uploads); later ones only lead in.
            const int warm = r == 0 ? bf.warmup : o.warm_per_stretch;
            run_chunk(*renderers[c], bf, meshes, first, last - first, warm, runs[c], progress);
        }
    }
    for (std::size_t c = 0; c < configs.size(); ++c) {
        finish_run(runs[c]);
        std::vector<geo::MaskScore> scores;
        std::vector<geo::MaskScore> wide[2];
        const auto& ref = refs[kinds_of(configs[c])];
        for (std::size_t k = 0; k < result.sampled.size(); ++k) {
            const std::vector<std::uint8_t> mask =
                renderers[c]->render_mask(frame_of(result.sampled[k]), meshes);
            scores.push_back(geo::score_masks(mask, ref[k], width, height, 1));
            // Wider tolerances: the sketch style's jittered strokes (Olejnik & Litchmore) are
            // scored at 1, 2 and 4 px; the exact-line configurations gain little from them.
            wide[0].push_back(geo::score_masks(mask, ref[k], width, height, 2));
            wide[1].push_back(geo::score_masks(mask, ref[k], width, height, 4));
            if (!o.masks_dir.empty()) {
                write_png(mask_path(configs[c].label, result.sampled[k]),
                          Image{width, height, 1, mask});
            }
        }
        result.rows.push_back({configs[c], std::move(runs[c]), summarise(std::move(scores)),
                               summarise(std::move(wide[0])), summarise(std::move(wide[1]))});
    }
    return result;
}

std::vector<Goal> judge_goals(const std::vector<SweepRow>& rows) {
    std::vector<Goal> goals;
    const SweepRow* fast = find_row(rows, "fast");
    const SweepRow* balanced = find_row(rows, "balanced");
    const SweepRow* high = find_row(rows, "high");
    const SweepRow* outline = find_row(rows, "image-outline");
    if (high) {
        goals.push_back(
            {"high: mean F1 >= 0.97", high->score.mean_f1 >= 0.97,
             printf_text("mean F1 %.4f (min %.4f)", high->score.mean_f1, high->score.min_f1)});
    }
    if (fast && high) {
        const double ratio = fast->run.stats.p50_ms / std::max(high->run.stats.p50_ms, 1e-9);
        goals.push_back({"fast: p50 <= 0.6 x p50 of high", ratio <= 0.6,
                         printf_text("fast p50 %.2f ms, high p50 %.2f ms: %.2fx",
                                     fast->run.stats.p50_ms, high->run.stats.p50_ms, ratio)});
    }
    if (balanced && outline) {
        const double ratio = balanced->run.stats.p50_ms / std::max(outline->run.stats.p50_ms, 1e-9);
        goals.push_back({"balanced: F1 above the image-space baseline",
                         balanced->score.mean_f1 > outline->score.mean_f1,
                         printf_text("balanced mean F1 %.4f, baseline %.4f",
                                     balanced->score.mean_f1, outline->score.mean_f1)});
        goals.push_back(
            {"balanced: p50 <= 1.5 x p50 of the baseline", ratio <= 1.5,
             printf_text("balanced p50 %.2f ms, baseline p50 %.2f ms: %.2fx",
                         balanced->run.stats.p50_ms, outline->run.stats.p50_ms, ratio)});
    }
    return goals;
}

std::string sweep_json(const BenchMeta& meta, const SweepResult& r,
                       const std::vector<Goal>& goals) {
    Json j = meta_json(meta);
    j["scored_frames"] = r.sampled;
    j["scored_frame_times_s"] = r.sampled_seconds;
    j["score_tolerance_px"] = 1;
    j["reference_cpu_ms"] = r.reference_ms;
    j["reference_rays"] = r.reference_rays;
    Json configs = Json::array();
    for (const SweepRow& row : r.rows) {
        Json c = Json::object();
        c["what"] = row.config.what;
        c.update(run_json(row.run));
        Json per_frame = Json::array();
        for (const geo::MaskScore& s : row.score.per_sample) per_frame.push_back(s.f1);
        c["f1"] = Json{{"mean", row.score.mean_f1},
                       {"min", row.score.min_f1},
                       {"precision_mean", row.score.mean_precision},
                       {"recall_mean", row.score.mean_recall},
                       {"per_frame", std::move(per_frame)}};
        c["f1_2px"] = Json{{"mean", row.score_2px.mean_f1},
                           {"precision_mean", row.score_2px.mean_precision},
                           {"recall_mean", row.score_2px.mean_recall}};
        c["f1_4px"] = Json{{"mean", row.score_4px.mean_f1},
                           {"precision_mean", row.score_4px.mean_precision},
                           {"recall_mean", row.score_4px.mean_recall}};
        configs.push_back(std::move(c));
    }
    j["configs"] = std::move(configs);
    j["goals"] = goals_json(goals);
    return json_text(j);
}

void print_sweep_table(std::FILE* out, const SweepResult& r, const std::vector<Goal>& goals) {
    std::fprintf(out, "\n%-24s %8s %8s %8s %8s %8s %8s %8s %10s\n", "config", "p50 ms", "p95",
                 "p99", "mean", "F1", "min F1", "prec", "recall");
    for (const SweepRow& row : r.rows) {
        const FrameTimeStats& t = row.run.stats;
        std::fprintf(out, "%-24s %8.2f %8.2f %8.2f %8.2f %8.4f %8.4f %8.4f %10.4f\n",
                     row.config.label.c_str(), t.p50_ms, t.p95_ms, t.p99_ms, t.mean_ms,
                     row.score.mean_f1, row.score.min_f1, row.score.mean_precision,
                     row.score.mean_recall);
    }
    std::fprintf(out, "F1 at 1 px tolerance over %zu frames; reference masks took %.1f s of CPU\n",
                 r.sampled.size(), r.reference_ms / 1000.0);
    std::fprintf(out, "\n%-24s %8s %8s %8s %8s %8s %8s\n", "config", "P 2px", "R 2px", "F1 2px",
                 "P 4px", "R 4px", "F1 4px");
    for (const SweepRow& row : r.rows) {
        std::fprintf(out, "%-24s %8.4f %8.4f %8.4f %8.4f %8.4f %8.4f\n", row.config.label.c_str(),
                     row.score_2px.mean_precision, row.score_2px.mean_recall, row.score_2px.mean_f1,
                     row.score_4px.mean_precision, row.score_4px.mean_recall,
                     row.score_4px.mean_f1);
    }
    print_goals(out, goals, 46);
}

}  // namespace bz::app
