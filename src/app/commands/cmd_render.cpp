#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "app/commands/camera_args.h"
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/headless_gl.h"
#include "app/line_method_profile.h"
#include "app/model_source.h"
#include "app/vector_export.h"
#include "cli/render_args.h"
#include "core/budgets.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/image_stats.h"
#include "core/io/output_path.h"
#include "core/text/printable.h"
#include "geometry/line_mesh/line_mesh.h"
#include "render/renderer.h"
#include "scene/presentation_clock.h"
#include "scene/style_table.h"

namespace bz::app {

namespace {

void print_timings(const render::Renderer& r,
                   const std::vector<std::vector<gl::PassTime>>& frames) {
    if (frames.empty()) return;
    std::fprintf(stdout, "pass        mean ms  (%zu frames, %dx%d, glFinish + CPU clock)\n",
                 frames.size(), r.width(), r.height());
    double total = 0.0;
    for (std::size_t p = 0; p < frames.front().size(); ++p) {
        double sum = 0.0;
        for (const auto& f : frames) sum += f[p].ms;
        const double mean = sum / static_cast<double>(frames.size());
        total += mean;
        std::fprintf(stdout, "%-10s %8.2f\n", frames.front()[p].name.c_str(), mean);
    }
    std::fprintf(stdout, "%-10s %8.2f\n", "total", total);
    const auto& s = r.stats();
    std::fprintf(stdout, "objects %zu, triangles %zu, feature edges %zu\n", s.objects_drawn,
                 s.triangles_submitted, s.feature_edges);
    const render::EdgeCullStats& c = s.edge_culling;
    if (c.clusters > 0) {
        std::fprintf(stdout,
                     "edge clusters %zu: %zu outside the view, %zu facing away, %zu one way, "
                     "%zu hidden by the prepass; edges tested %zu of %zu",
                     c.clusters, c.outside_frustum, c.facing_away, c.one_way,
                     r.hiz_hidden_clusters(), c.edges_dispatched, c.edges);
        if (c.edges_prefiltered > 0)
            std::fprintf(stdout, " (of %zu the CPU tested first)", c.edges_prefiltered);
        std::fprintf(stdout, "\n");
    }
    const render::TriangleCullStats& t = s.triangle_culling;
    if (t.clusters > 0) {
        std::fprintf(stdout,
                     "triangle clusters %zu: %zu outside the view, %zu facing away, %zu one-sided; "
                     "prepass triangles %zu of %zu (%zu of them rasterised by compute)\n",
                     t.clusters, t.outside_frustum, t.facing_away, t.one_sided, t.triangles_drawn,
                     t.triangles, t.triangles_computed);
    }
    // The mip-chain bloom's levels past the first: drawn one by one, or walked in one dispatch.
    // Not "bloom ...": tools read the pass table by its first word
    // (tests/cli/render_pass_table.sh).
    if (const render::BloomChainSplit b = r.stats().bloom_chain; b.drawn + b.walked > 0) {
        std::fprintf(stdout,
                     "mip-chain bloom past level 0: %zu levels drawn, %zu walked in one dispatch\n",
                     b.drawn, b.walked);
    }
    // RenderSettings::first_downsample's choice (automatic: by the frame before's lit tiles).
    if (const render::FirstDownsampleRead d = r.stats().first_downsample;
        d != render::FirstDownsampleRead::none) {
        std::fprintf(stdout, "first bloom downsample read %s\n",
                     d == render::FirstDownsampleRead::whole_image
                         ? "the whole beam image"
                         : "the beam image under the marked tiles only");
    }
    // Where auto timed both clear paths (a hardware GPU), what it found.
    if (const std::optional<render::ClearTiming> ct = r.colour_clear_timing()) {
        std::fprintf(stdout,
                     "colour clears by %s (timed at %dx%d: glClear %.3f ms, compute %.3f ms)\n",
                     ct->compute_is_faster() ? "compute" : "glClear", r.width(), r.height(),
                     ct->pipeline_ms, ct->compute_ms);
    }
}

// Lays out `copies` instances on a square grid in the xz plane; returns their joint bounds.
geo::Bounds place_copies(scene::FrameList& frame, scene::MeshId id, const geo::Bounds& one,
                         int copies, double spacing, glm::vec3 color, bool smooth) {
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(copies))));
    const glm::dvec3 step = glm::dvec3(one.max - one.min) * spacing;
    geo::Bounds all = one;
    for (int i = 0; i < copies; ++i) {
        const glm::dvec3 offset(step.x * (i % side), 0.0, -step.z * (i / side));
        frame.items.push_back(
            {id, glm::translate(glm::dmat4(1.0), offset), color, 1.0f, true, smooth});
        all.min = glm::min(all.min, one.min + glm::vec3(offset));
        all.max = glm::max(all.max, one.max + glm::vec3(offset));
    }
    return all;
}

}  // namespace

int cmd_render(Args args) {
    int exit_code = 0;
    render::RenderSettings settings;
    const auto parse_checked = [&settings](Args a) {
        RenderOptions parsed = parse_render_args(a);  // names checked there
        settings = render::preset(parsed.preset);
        settings.beam = render::beam_look(parsed.beam);
        if (!parsed.line_method.empty())
            settings.method = render::parse_line_method(parsed.line_method);
        return parsed;
    };
    const std::optional<RenderOptions> parsed =
        parse_command("render", args, render_usage().c_str(), parse_checked, &exit_code);
    if (!parsed) return exit_code;
    const RenderOptions& o = *parsed;
    const std::filesystem::path inputs[] = {o.input};
    check_output_file("--out", o.out, kPngOutput, inputs, o.overwrite);
    if (!o.mask.empty()) check_output_file("--mask", o.mask, kPngOutput, inputs, o.overwrite);
    if (!o.svg.empty()) check_output_file("--svg", o.svg, kSvgOutput, inputs, o.overwrite);
    geo::MeshReport report;
    geo::AdjacencyMesh mesh = geo::build_line_mesh(load_model_source(o.input), &report);
    if (mesh.triangle_count() == 0) throw UserError(printable(o.input) + ": no usable triangles");
    const std::int64_t drawn = static_cast<std::int64_t>(mesh.triangle_count()) * o.copies;
    if (drawn > budget::kCopiesTriangles) {
        throw UserError("--copies " + std::to_string(o.copies) + " of " + printable(o.input) +
                        " (" + std::to_string(mesh.triangle_count()) + " triangles) makes " +
                        std::to_string(drawn) + " triangles, over the budget of " +
                        std::to_string(budget::kCopiesTriangles));
    }

    auto context = make_headless_context();
    check_image_size(*context, "--size", o.camera.size.x, o.camera.size.y);
    scene::MeshLibrary meshes;
    scene::FrameList frame;
    const geo::Bounds one = geo::compute_bounds(mesh.positions);
    const scene::MeshId id = meshes.add(o.input, std::move(mesh));
    const geo::Bounds bounds =
        place_copies(frame, id, one, o.copies, o.copy_step, glm::vec3(o.color), o.smooth);
    frame.camera = camera_for(o.camera, bounds);
    frame.style = o.style;

    settings.count_edges = o.repeat > 0;
    settings.cubic_smoothing = o.smoothing;
    settings.one_sided_outlines = o.one_sided;
    settings.cluster_culling = o.cluster_culling;
    settings.hiz_culling = o.hiz_culling;
    settings.prepass_raster = o.prepass_raster;
    settings.bloom_chain = o.bloom_chain;
    settings.edge_prefilter = o.edge_prefilter;
    settings.colour_clears = o.colour_clears;
    settings.material_lines = o.material_lines;
    settings.intersection_lines = o.intersection_lines;
    // A one-off frame measures nothing: it uses the machine's kept crossing, if any.
    const LineMethodProfile line_methods = user_line_method_profile(Calibration::kept_only);
    settings.auto_compute_from_triangles = line_methods.threshold();
    if (o.repeat > 0) std::fprintf(stdout, "%s\n", line_methods.describe().c_str());
    render::Renderer renderer(settings, o.camera.size.x, o.camera.size.y,
                              o.repeat > 0 ? gl::TimingMethod::cpu_finish : gl::TimingMethod::off);
    std::vector<std::vector<gl::PassTime>> timings;
    const int frames = std::max(o.repeat, 1) + (o.repeat > 0 ? 2 : 0);  // 2 warm-up frames
    scene::PresentationClock clock;  // --repeat: one nominal 60 Hz frame per picture
    render::IntersectionStats first_intersections;
    double later_intersection_ms = 0.0;
    for (int i = 0; i < frames; ++i) {
        clock.advance_nominal();
        clock.stamp(frame);
        renderer.render(frame, meshes, render::Renderer::kOffscreen);
        if (i == 0) first_intersections = renderer.stats().intersections;
        if (i > 0) later_intersection_ms += renderer.stats().intersections.update_ms;
        if (o.repeat > 0 && i >= 2) timings.push_back(renderer.pass_times());
    }
    const Image picture{o.camera.size.x, o.camera.size.y, 4, renderer.read_color()};
    write_png(o.out, picture);
    if (o.lit_share) {
        std::fprintf(stdout, "lit share (brightest channel above 1/255): %.2f%%\n",
                     100.0 * lit_share(picture));
    }
    if (!o.mask.empty())
        write_png(o.mask,
                  Image{o.camera.size.x, o.camera.size.y, 1, renderer.render_mask(frame, meshes)});
    if (!o.svg.empty()) {
        render::FrameSvgOptions svg;
        svg.reference.crease_angle_deg = settings.crease_angle_deg;
        svg.reference.material_lines = settings.material_lines;
        svg.reference.intersection_lines = settings.intersection_lines;
        std::fprintf(
            stdout, "%s\n",
            export_frame_svg(o.svg, frame, meshes, o.camera.size.x, o.camera.size.y, svg).c_str());
    }
    print_timings(renderer, timings);
    if (o.repeat > 0 && settings.intersection_lines) {
        // The crossings are computed on the first frame and kept: what that costs, and what
        // a frame costs once they are.
        const render::FrameStats& s = renderer.stats();
        std::fprintf(stdout,
                     "intersection lines: %zu segments (%zu drawn) from %zu overlapping pairs of "
                     "%zu objects; first frame %.2f ms CPU (%zu pairs, %zu meshes computed), "
                     "later frames %.3f ms mean\n",
                     s.intersections.segments, s.intersection_records, s.intersections.pairs,
                     s.intersections.placements, first_intersections.update_ms,
                     first_intersections.pairs_computed, first_intersections.meshes_computed,
                     later_intersection_ms / std::max(1, frames - 1));
    }
    if (context->debug().error_count() > 0) {
        std::fprintf(stderr, "beamzone render: %d OpenGL error(s) reported\n",
                     context->debug().error_count());
        return 1;
    }
    return 0;
}

}  // namespace bz::app
