#include "app/bench/bench_accuracy.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <system_error>

#include "app/bench/bench_text.h"
#include "app/model_source.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/image_io.h"
#include "core/io/file_io.h"
#include "geometry/line_mesh/line_mesh.h"
#include "render/camera/camera_framing.h"
#include "render/reference_frame.h"

namespace bz::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Bump when the reference's definition changes, so cached masks are recomputed.
constexpr int kReferenceCacheVersion = 1;

// A file-name-safe stem for a model path: "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf" ->
// "CesiumMilkTruck.gltf".
std::string model_stem(const std::string& path) {
    std::string s = fs::path(path).filename().string();
    for (char& c : s) {
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_'))
            c = '_';
    }
    return s;
}

fs::path resolve(const AccuracyOptions& o, const std::string& path) {
    const fs::path p(path);
    return p.is_absolute() ? p : o.models_dir / p;
}

// The reference mask of one view, from the cache folder when an earlier run computed it for
// the same model file, camera, size and reference version.
struct ReferenceCache {
    fs::path dir;

    fs::path path_for(const std::string& model_text, const scene::Camera& c, int w, int h) const {
        Hasher hsh;
        hsh.value(kReferenceCacheVersion);
        hsh.text(model_text);
        for (const glm::dvec3& v : {c.eye, c.target, c.up}) hsh.value(v);
        hsh.value(c.fov_y_deg);
        hsh.value(c.near);
        hsh.value(c.far);
        hsh.value(w);
        hsh.value(h);
        char name[40];
        std::snprintf(name, sizeof name, "%016llx.png",
                      static_cast<unsigned long long>(hsh.digest()));
        return dir / name;
    }
};

std::vector<std::uint8_t> lit(const Image& img) {
    std::vector<std::uint8_t> out(img.pixels.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = img.pixels[i] >= 128 ? 255 : 0;
    return out;
}

// RGBA picture of a mask against the reference: white = both, red = drawn but not in the
// reference (a hidden line leaking), cyan = in the reference but not drawn (a missing line).
// Matching is exact per pixel here; the scores use the tolerance.
Image diff_image(const std::vector<std::uint8_t>& test, const std::vector<std::uint8_t>& ref, int w,
                 int h) {
    Image img{w, h, 4, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h) * 4, 0)};
    for (std::size_t i = 0; i < test.size(); ++i) {
        const bool t = test[i] != 0, r = ref[i] != 0;
        std::uint8_t* p = &img.pixels[i * 4];
        p[3] = 255;
        if (t && r) {
            p[0] = p[1] = p[2] = 255;
        } else if (t) {
            p[0] = 255;
        } else if (r) {
            p[1] = p[2] = 255;
        }
    }
    return img;
}

void summarise(AccuracyRow& row) {
    if (row.views.empty()) return;
    row.mean_f1 = row.mean_precision = row.mean_recall = row.mean_p50_ms = 0.0;
    row.min_f1 = 1.0;
    for (const AccuracyViewScore& v : row.views) {
        row.mean_f1 += v.score.f1;
        row.mean_precision += v.score.precision;
        row.mean_recall += v.score.recall;
        row.mean_p50_ms += v.p50_ms;
        if (v.score.f1 <= row.min_f1) {
            row.min_f1 = v.score.f1;
            row.worst_view = v.model + " " + v.view;
        }
    }
    const auto n = static_cast<double>(row.views.size());
    row.mean_f1 /= n;
    row.mean_precision /= n;
    row.mean_recall /= n;
    row.mean_p50_ms /= n;
}

// The same view from the command line: `render` and `reference` place the camera alike for
// the same arguments (app/camera_args), and derive these near and far planes from --eye.
std::string view_command(const char* command, const AccuracyViewInfo& v, const AccuracyOptions& o) {
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "%s %s --size %dx%d --fov %.17g --eye %.17g,%.17g,%.17g --target %.17g,%.17g,%.17g",
        command, v.file.c_str(), o.width, o.height, v.camera.fov_y_deg, v.camera.eye.x,
        v.camera.eye.y, v.camera.eye.z, v.camera.target.x, v.camera.target.y, v.camera.target.z);
    return buf;
}

const AccuracyRow* find(const std::vector<AccuracyRow>& rows, const std::string& label) {
    for (const AccuracyRow& r : rows) {
        if (r.config.label == label) return &r;
    }
    return nullptr;
}

}  // namespace

const std::vector<AccuracyModel>& default_accuracy_models() {
    static const std::vector<AccuracyModel> models = {
        {"IFC/AC14-FZK-Haus.ifc", "architecture (IFC house: rafters under the roof)"},
        {"Collada/COLLADA.dae", "letters standing on a plate (Collada)"},
        {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "CAD assembly (glTF binary)"},
        {"X3D/ComputerKeyboard.x3d", "product model, keys in a case (X3D)"},
        {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "vehicle (glTF)"},
        {"MS3D/jeep1.ms3d", "vehicle (MilkShape)"},
        {"Q3D/E-AT-AT.q3o", "walker vehicle (Quick3D)"},
        {"Collada/teapots.DAE", "instanced teapots (Collada)"},
        {"PLY/Wuson.ply", "organic (PLY)"},
        {"Collada/duck.dae", "organic (Collada)"},
        {"COB/dwarf.cob", "character (Caligari)"},
        {"MD2/faerie.md2", "character (Quake 2)"},
        {"OBJ/spider.obj", "organic, thin legs (OBJ)"},
        {"X/BCN_Epileptic.X", "character (DirectX)"},
        {"3DS/fels.3ds", "rock (3DS)"},
        {"BLEND/HUMAN.blend", "human figure (Blender)"},
    };
    return models;
}

std::vector<AccuracyView> accuracy_views(const geo::Bounds& bounds, double aspect) {
    constexpr double kFov = 50.0;  // render's default
    const scene::Camera framed = render::frame_bounds(bounds, kFov, aspect);
    const glm::dvec3 centre = framed.target;
    const glm::dvec3 offset = framed.eye - centre;
    const double distance = glm::length(offset);
    const double radius = std::max(static_cast<double>(bounds.radius()), 1e-6);
    // The same rule as `render --eye`: near and far fit the bounds around the target.
    auto look_from = [&](const glm::dvec3& eye) {
        scene::Camera c = framed;
        c.eye = eye;
        const double d = glm::length(eye - centre);
        c.near = std::max(d - radius * 1.5, d * 1e-3);
        c.far = d + radius * 1.5;
        return c;
    };
    std::vector<AccuracyView> out;
    out.push_back({"framed", framed});
    out.push_back({"behind", look_from(centre + glm::dvec3(-offset.x, offset.y, -offset.z))});
    out.push_back({"close", look_from(centre + offset * 0.4)});
    // 70 degrees above the horizon, from the front-left.
    const double el = glm::radians(70.0);
    const glm::dvec3 high_dir(-0.6 * std::cos(el), std::sin(el), 0.8 * std::cos(el));
    out.push_back({"above", look_from(centre + glm::normalize(high_dir) * distance)});
    return out;
}

std::vector<SweepConfig> accuracy_configs() {
    std::vector<SweepConfig> out;
    for (const std::string& name : render::preset_names())
        out.push_back({name, "preset " + name, render::preset(name)});
    SweepConfig outline{"image-outline", "baseline: Sobel on prepass depth + normals",
                        render::preset("balanced")};
    outline.settings.method = render::LineMethod::image_outline;
    out.push_back(outline);
    return out;
}

AccuracyResult run_accuracy(const AccuracyOptions& o, gl::TimingMethod timing) {
    AccuracyResult result;
    const std::vector<AccuracyModel>& models =
        o.models.empty() ? default_accuracy_models() : o.models;
    const double aspect = static_cast<double>(o.width) / o.height;
    const fs::path masks_dir = o.out / "masks";
    const fs::path diffs_dir = o.out / "diffs";
    const ReferenceCache cache{o.out / "reference-cache"};
    for (const fs::path& d : {masks_dir, diffs_dir, cache.dir}) {
        std::error_code ec;
        fs::create_directories(d, ec);
        if (ec) throw UserError(d.string() + ": cannot create: " + ec.message());
    }

    const std::vector<SweepConfig> configs = accuracy_configs();
    std::vector<std::unique_ptr<render::Renderer>> renderers;
    for (SweepConfig c : configs) {
        c.settings.auto_compute_from_triangles = o.auto_compute_from_triangles;
        result.rows.push_back({c, {}, 0.0, 1.0, 0.0, 0.0, 0.0, {}});
        renderers.push_back(
            std::make_unique<render::Renderer>(c.settings, o.width, o.height, timing));
    }
    // One library for every model: the renderers' GPU mesh caches are keyed by mesh id.
    scene::MeshLibrary meshes;
    for (const AccuracyModel& m : models) {
        const fs::path file = resolve(o, m.path);
        geo::AdjacencyMesh mesh;
        std::string model_text;
        try {
            mesh = geo::build_line_mesh(load_model_source(file.string()));
            if (mesh.triangle_count() == 0)
                throw UserError(file.string() + ": no usable triangles");
            model_text = read_file(file);
        } catch (const UserError& e) {
            result.skipped.push_back(e.what());
            std::fprintf(stderr, "accuracy: skipping %s\n", e.what());
            continue;
        }
        const geo::Bounds bounds = geo::compute_bounds(mesh.positions);
        const std::size_t triangles = mesh.triangle_count();
        const scene::MeshId id = meshes.add(m.path, std::move(mesh));
        const std::string stem = model_stem(m.path);
        for (const AccuracyView& view : accuracy_views(bounds, aspect)) {
            scene::FrameList frame;
            frame.camera = view.camera;
            frame.items.push_back({id, glm::dmat4(1.0), glm::vec3(0.2f, 1.0f, 0.3f), 1.0f, true});
            AccuracyViewInfo info{stem,        file.string(), m.kind, view.name,
                                  view.camera, triangles,     false};

            // The exact mask, cached across runs.
            const fs::path cached = cache.path_for(model_text, view.camera, o.width, o.height);
            std::vector<std::uint8_t> ref;
            if (fs::exists(cached)) {
                const Image img = read_png(cached, 1);
                if (img.width == o.width && img.height == o.height) {
                    ref = lit(img);
                    info.reference_cached = true;
                }
            }
            if (ref.empty()) {
                const auto t0 = Clock::now();
                ref = render::reference_frame_mask(frame, meshes, o.width, o.height);
                result.reference_ms +=
                    std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
                write_png(cached, Image{o.width, o.height, 1, ref});
            }
            const std::string base = stem + "_" + view.name;
            write_png(masks_dir / (base + "_reference.png"), Image{o.width, o.height, 1, ref});

            // Timing: every configuration on this view, interleaved frame by frame so a
            // drifting load treats them alike.
            BenchFrames bf;
            bf.warmup = o.warmup;
            bf.frames.assign(static_cast<std::size_t>(o.warmup + o.frames), frame);
            bf.seconds.assign(bf.frames.size(), 0.0);
            std::vector<RunResult> runs;
            for (const SweepConfig& c : configs) runs.push_back(start_run(bf, c.label, c.settings));
            for (int f = 0; f < o.frames; ++f) {
                for (std::size_t c = 0; c < configs.size(); ++c) {
                    run_chunk(*renderers[c], bf, meshes, f, 1, f == 0 ? o.warmup : 0, runs[c], {});
                }
            }
            for (std::size_t c = 0; c < configs.size(); ++c) {
                finish_run(runs[c]);
                const std::vector<std::uint8_t> mask = renderers[c]->render_mask(frame, meshes);
                AccuracyViewScore s{stem, view.name,
                                    geo::score_masks(mask, ref, o.width, o.height, o.tolerance_px),
                                    runs[c].stats.p50_ms};
                write_png(masks_dir / (base + "_" + configs[c].label + ".png"),
                          Image{o.width, o.height, 1, mask});
                write_png(diffs_dir / (base + "_" + configs[c].label + ".png"),
                          diff_image(mask, ref, o.width, o.height));
                result.rows[c].views.push_back(s);
            }
            result.views.push_back(info);
            if (o.progress) {
                std::fprintf(stderr, "%-26s %-7s", stem.c_str(), view.name.c_str());
                for (std::size_t c = 0; c < configs.size(); ++c) {
                    const AccuracyViewScore& s = result.rows[c].views.back();
                    std::fprintf(stderr, "  %s %.4f (P %.3f R %.3f) %.1f ms",
                                 configs[c].label.c_str(), s.score.f1, s.score.precision,
                                 s.score.recall, s.p50_ms);
                }
                std::fprintf(stderr, "\n");
            }
        }
    }
    for (AccuracyRow& r : result.rows) summarise(r);
    return result;
}

std::vector<Goal> judge_accuracy_goals(const AccuracyResult& r) {
    std::vector<Goal> goals;
    for (const std::string& name : render::preset_names()) {
        const AccuracyRow* row = find(r.rows, name);
        if (!row) continue;
        goals.push_back({name + ": mean F1 >= 0.99", row->mean_f1 >= 0.99,
                         printf_text("mean F1 %.4f", row->mean_f1)});
        goals.push_back(
            {name + ": no view below F1 0.95", row->min_f1 >= 0.95,
             printf_text("worst view F1 %.4f", row->min_f1) + " (" + row->worst_view + ")"});
    }
    const AccuracyRow* high = find(r.rows, "high");
    const AccuracyRow* balanced = find(r.rows, "balanced");
    if (high && balanced) {
        goals.push_back(
            {"high: mean F1 >= balanced's", high->mean_f1 >= balanced->mean_f1,
             printf_text("high %.4f, balanced %.4f", high->mean_f1, balanced->mean_f1)});
        goals.push_back({"high: worst view >= balanced's", high->min_f1 >= balanced->min_f1,
                         printf_text("high %.4f, balanced %.4f", high->min_f1, balanced->min_f1)});
    }
    return goals;
}

std::string accuracy_json(const BenchMeta& meta, const AccuracyOptions& o, const AccuracyResult& r,
                          const std::vector<Goal>& goals) {
    Json j = meta_json(meta);
    j["models_dir"] = o.models_dir.string();
    j["score_tolerance_px"] = o.tolerance_px;
    j["score_tolerance_note"] =
        "Chebyshev: a lit pixel matches a lit pixel among its 8 neighbours (1.5 px Euclidean "
        "on the pixel grid)";
    j["timed_frames_per_view"] = o.frames;
    j["reference_cpu_ms"] = r.reference_ms;
    j["skipped"] = r.skipped;
    const auto vec = [](const glm::dvec3& x) { return Json::array({x.x, x.y, x.z}); };
    Json views = Json::array();
    for (const AccuracyViewInfo& v : r.views) {
        Json view = Json::object();
        view["model"] = v.model;
        view["kind"] = v.kind;
        view["view"] = v.view;
        view["triangles"] = v.triangles;
        view["eye"] = vec(v.camera.eye);
        view["target"] = vec(v.camera.target);
        view["fov_y_deg"] = v.camera.fov_y_deg;
        view["near"] = v.camera.near;
        view["far"] = v.camera.far;
        view["reference_command"] = view_command("reference", v, o);
        views.push_back(std::move(view));
    }
    j["views"] = std::move(views);
    Json configs = Json::array();
    for (const AccuracyRow& row : r.rows) {
        Json c = Json::object();
        c["label"] = row.config.label;
        c["what"] = row.config.what;
        c["mean_f1"] = row.mean_f1;
        c["min_f1"] = row.min_f1;
        c["worst_view"] = row.worst_view;
        c["precision_mean"] = row.mean_precision;
        c["recall_mean"] = row.mean_recall;
        c["frame_ms_p50_mean"] = row.mean_p50_ms;
        Json per_view = Json::array();
        for (const AccuracyViewScore& v : row.views) {
            Json pv = Json::object();
            pv["model"] = v.model;
            pv["view"] = v.view;
            pv["precision"] = v.score.precision;
            pv["recall"] = v.score.recall;
            pv["f1"] = v.score.f1;
            pv["test_lit"] = v.score.test_lit;
            pv["ref_lit"] = v.score.ref_lit;
            pv["frame_ms_p50"] = v.p50_ms;
            per_view.push_back(std::move(pv));
        }
        c["per_view"] = std::move(per_view);
        configs.push_back(std::move(c));
    }
    j["configs"] = std::move(configs);
    j["goals"] = goals_json(goals);
    return json_text(j);
}

void print_accuracy_table(std::FILE* out, const AccuracyResult& r, const std::vector<Goal>& goals,
                          int tolerance_px) {
    std::fprintf(out, "\n%-16s %9s %8s %8s %8s %8s  %s\n", "config", "frame ms", "mean F1",
                 "min F1", "prec", "recall", "worst view");
    for (const AccuracyRow& row : r.rows) {
        std::fprintf(out, "%-16s %9.2f %8.4f %8.4f %8.4f %8.4f  %s\n", row.config.label.c_str(),
                     row.mean_p50_ms, row.mean_f1, row.min_f1, row.mean_precision, row.mean_recall,
                     row.worst_view.c_str());
    }
    std::fprintf(out,
                 "%zu views; F1 at %d px (Chebyshev); frame ms = mean over views of each view's "
                 "p50; new reference masks took %.1f s of CPU\n",
                 r.views.size(), tolerance_px, r.reference_ms / 1000.0);
    for (const std::string& s : r.skipped) std::fprintf(out, "skipped: %s\n", s.c_str());
    print_goals(out, goals, 40);
}

}  // namespace bz::app
