// beamzone reference: the exact CPU line mask (geometry/reference/reference.h) of a model, or of a
// level's benchmark frame, in the same format as `render --mask`.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/bench/bench_scene.h"
#include "app/commands/camera_args.h"
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/model_source.h"
#include "app/vector_export.h"
#include "cli/reference_args.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/io/output_path.h"
#include "core/text/printable.h"
#include "geometry/line_mesh/line_mesh.h"
#include "level/loader.h"
#include "render/reference_frame.h"
#include "scene/camera_check.h"

namespace bz::app {

namespace {

// The frame the benchmark draws at `seconds`: one simulation tick per 1/60 s.
scene::FrameList level_frame(BenchScene& scene, double seconds, double aspect) {
    const auto ticks = std::max<long>(1, std::lround(seconds / kBenchStep));
    scene::FrameList f;
    for (long i = 0; i < ticks; ++i) scene.next(f, aspect);
    if (const std::string why = scene::camera_problem(f.camera); !why.empty())
        throw UserError("at " + std::to_string(seconds) +
                        " s the camera cannot make a picture: " + why);
    return f;
}

int run(const ReferenceOptions& o) {
    const glm::ivec2 size = o.camera.size;
    const double aspect = static_cast<double>(size.x) / size.y;
    render::ReferenceFrameOptions ro;
    ro.crease_angle_deg = o.crease;
    ro.material_lines = o.material_lines;
    ro.intersection_lines = o.intersection_lines;
    geo::ReferenceStats stats;
    std::vector<std::uint8_t> mask;
    std::string svg_log;
    const auto svg = [&](const scene::FrameList& frame, const scene::MeshLibrary& meshes) {
        render::FrameSvgOptions so;
        so.reference = ro;
        return export_frame_svg(o.svg, frame, meshes, size.x, size.y, so);
    };
    const auto t0 = std::chrono::steady_clock::now();
    if (!o.level.empty()) {
        level::LoadResult loaded = level::load_level_file(o.level);
        if (!loaded.ok()) {
            for (const level::Diagnostic& d : loaded.errors)
                std::fprintf(stderr, "%s\n", level::format(d).c_str());
            return 1;
        }
        // The level's own switch draws them as the game would.
        if (loaded.level->render.material_lines.value_or(false)) ro.material_lines = true;
        if (loaded.level->render.intersection_lines.value_or(false)) ro.intersection_lines = true;
        BenchScene scene(std::move(*loaded.level), std::nullopt);
        const scene::FrameList frame = level_frame(scene, *o.time, aspect);
        mask = render::reference_frame_mask(frame, scene.meshes(), size.x, size.y, ro, &stats);
        if (!o.svg.empty()) svg_log = svg(frame, scene.meshes());
    } else {
        geo::AdjacencyMesh mesh = geo::build_line_mesh(load_model_source(o.input));
        if (mesh.triangle_count() == 0)
            throw UserError(printable(o.input) + ": no usable triangles");
        const geo::Bounds bounds = geo::compute_bounds(mesh.positions);
        scene::MeshLibrary meshes;
        scene::FrameList frame;
        frame.items.push_back(
            {meshes.add(o.input, std::move(mesh)), glm::dmat4(1.0), glm::vec3(1.0f), 1.0f, true});
        frame.camera = camera_for(o.camera, bounds);
        frame.style = o.style;
        mask = render::reference_frame_mask(frame, meshes, size.x, size.y, ro, &stats);
        if (!o.svg.empty()) svg_log = svg(frame, meshes);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    write_png(o.mask, Image{size.x, size.y, 1, std::move(mask)});
    std::printf(
        "%s: %zu lit pixels; %zu feature edges (%zu on screen), %zu occluder triangles, %zu rays, "
        "%.0f ms\n",
        o.mask.c_str(), stats.lit_pixels, stats.feature_edges, stats.drawn_edges,
        stats.occluder_triangles, stats.rays, ms);
    if (!svg_log.empty()) std::printf("%s\n", svg_log.c_str());
    return 0;
}

}  // namespace

int cmd_reference(Args args) {
    int exit_code = 0;
    const std::optional<ReferenceOptions> parsed =
        parse_command("reference", args, kReferenceUsage, parse_reference_args, &exit_code);
    if (!parsed) return exit_code;
    const ReferenceOptions& o = *parsed;
    const std::filesystem::path inputs[] = {o.input, o.level};
    check_output_file("--mask", o.mask, kPngOutput, inputs, o.overwrite);
    if (!o.svg.empty()) check_output_file("--svg", o.svg, kSvgOutput, inputs, o.overwrite);
    return run(o);
}

}  // namespace bz::app
