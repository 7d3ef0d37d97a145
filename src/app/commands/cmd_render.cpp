#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "app/commands/camera_args.h"
#include "app/commands/cli_args.h"
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/headless_gl.h"
#include "app/line_method_profile.h"
#include "app/model_source.h"
#include "app/vector_export.h"
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

// The usage, with the style table's names and help (scene/style.h).
const std::string& usage() {
    static const std::string text =
        std::string(
            "usage: beamzone render INPUT [--eye x,y,z] [--target x,y,z] [--up x,y,z] [--fov DEG]\n"
            "                       [--near N] [--far F] [--size WxH] [--preset "
            "fast|balanced|high]\n"
            "                       [--line-method compute|geometry_shader|auto|image_outline]\n"
            "                       [--style NAME] [--shading flat|smooth] [--no-smoothing] "
            "[--one-sided]\n"
            "                       [--color r,g,b] [--out frame.png]\n"
            "                       [--mask mask.png] [--repeat N] [--copies N] [--beam "
            "classic|mame]\n"
            "                       [--lit-share] [--no-cluster-culling] [--svg lines.svg]\n"
            "                       [--overwrite]\n"
            "Renders a model file (or builtin:cube, builtin:sphere, builtin:grid) headless to PNG. "
            "Without "
            "--eye the camera frames the model's bounding\n"
            "box from a 3/4 view. --mask writes the 1-pixel visible-spine mask (255 = line).\n"
            "--style: the frame's style (default vector):\n") +
        scene::style_help() +
        std::string(
            "--shading: filled styles' normals.\n"
            "--no-smoothing: the halo style's silhouettes stay polygonal (no cubic smoothing).\n"
            "--one-sided: toon / pop-art outlines extruded outward and depth-tested, not centred.\n"
            "--repeat N renders N timed frames and prints the mean milliseconds of each pass.\n"
            "--copies N draws N instances of the model on a square grid in the xz plane (a scene "
            "of a\n"
            "chosen size for timing; the camera frames them all).\n"
            "--beam picks the vector beam's look (default mame, as `play` and `bench`).\n"
            "--no-cluster-culling draws whole meshes in the depth prepass and the fills (the same\n"
            "picture; for timing what culling triangle clusters saves).\n"
            "--lit-share prints the share of the picture's pixels whose brightest channel is "
            "above\n"
            "1/255 (the haze figure; tools/haze measures Bernardoni 2018's hallway with it).\n"
            "--svg writes the frame's exact visible lines (the CPU reference's) as SVG: polylines\n"
            "ordered for a pen plotter, one group per line kind, in the style's colours.\n"
            "An existing file at --out, --mask or --svg must be a PNG unless --overwrite is given; "
            "an "
            "input,\n"
            "a device, a FIFO or a folder there is never replaced.\n");
    return text;
}

struct RenderOptions {
    std::string input;
    CameraArgs camera;  // shared with `reference`, so both place the camera alike
    std::string preset = "balanced";
    std::string line_method;  // empty: the preset's
    scene::Style style = scene::Style::vector;
    bool smooth = true;      // filled styles: smooth vertex normals (--shading flat: faces)
    bool smoothing = true;   // halo: cubic silhouette smoothing (--no-smoothing: plain)
    bool one_sided = false;  // toon / pop-art: one-sided outline quads
    glm::dvec3 color{0.25, 1.0, 0.35};
    std::string out = "frame.png";
    std::string mask;
    std::string svg;
    int repeat = 0;
    int copies = 1;
    std::string beam{render::kDefaultBeamLook};
    bool lit_share = false;
    bool cluster_culling = true;
    bool overwrite = false;  // may replace an existing file that is not a PNG
};

RenderOptions parse(Args args) {
    RenderOptions o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (parse_camera_option(a, cur, o.camera)) continue;
        if (a == "--preset")
            o.preset = cur.value(a);
        else if (a == "--line-method")
            o.line_method = cur.value(a);
        else if (a == "--color")
            o.color = parse_vec3(a, cur.value(a));
        else if (a == "--out")
            o.out = cur.value(a);
        else if (a == "--mask")
            o.mask = cur.value(a);
        else if (a == "--svg")
            o.svg = cur.value(a);
        else if (a == "--repeat")
            o.repeat = parse_int(a, cur.value(a), 1, 100000);
        else if (a == "--copies")
            o.copies = parse_int(a, cur.value(a), 1, budget::kRenderCopies);
        else if (a == "--beam")
            o.beam = cur.value(a);
        else if (a == "--lit-share")
            o.lit_share = true;
        else if (a == "--no-cluster-culling")
            o.cluster_culling = false;
        else if (a == "--overwrite")
            o.overwrite = true;
        else if (a == "--style") {
            o.style = parse_style(a, cur.value(a));
        } else if (a == "--no-smoothing") {
            o.smoothing = false;
        } else if (a == "--one-sided") {
            o.one_sided = true;
        } else if (a == "--shading") {
            const std::string_view s = cur.value(a);
            if (s != "flat" && s != "smooth")
                throw UsageError("--shading: expected flat or smooth");
            o.smooth = s == "smooth";
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else if (o.input.empty()) {
            o.input = a;
        } else {
            throw UsageError("more than one INPUT given");
        }
    }
    if (o.input.empty()) throw UsageError("no INPUT model given");
    if (o.out == o.mask) throw UsageError("--out and --mask name the same file");
    if (!o.svg.empty() && (o.svg == o.out || o.svg == o.mask))
        throw UsageError("--svg names the same file as --out or --mask");
    validate_camera(o.camera);
    return o;
}

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
                     "edge clusters %zu: %zu outside the view, %zu facing away, %zu one way; "
                     "edges tested %zu of %zu\n",
                     c.clusters, c.outside_frustum, c.facing_away, c.one_way, c.edges_dispatched,
                     c.edges);
    }
    const render::TriangleCullStats& t = s.triangle_culling;
    if (t.clusters > 0) {
        std::fprintf(stdout,
                     "triangle clusters %zu: %zu outside the view, %zu facing away; "
                     "prepass triangles %zu of %zu\n",
                     t.clusters, t.outside_frustum, t.facing_away, t.triangles_drawn, t.triangles);
    }
}

// Lays out `copies` instances on a square grid in the xz plane; returns their joint bounds.
geo::Bounds place_copies(scene::FrameList& frame, scene::MeshId id, const geo::Bounds& one,
                         int copies, glm::vec3 color, bool smooth) {
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(copies))));
    const glm::dvec3 step = glm::dvec3(one.max - one.min) * 1.2;
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
        RenderOptions parsed = parse(a);
        try {
            settings = render::preset(parsed.preset);
            settings.beam = render::beam_look(parsed.beam);
            if (!parsed.line_method.empty())
                settings.method = render::parse_line_method(parsed.line_method);
        } catch (const UserError& e) {
            throw UsageError(e.what());  // an unknown preset name is a usage error
        }
        return parsed;
    };
    const std::optional<RenderOptions> parsed =
        parse_command("render", args, usage().c_str(), parse_checked, &exit_code);
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
    const geo::Bounds bounds = place_copies(frame, id, one, o.copies, glm::vec3(o.color), o.smooth);
    frame.camera = camera_for(o.camera, bounds);
    frame.style = o.style;

    settings.count_edges = o.repeat > 0;
    settings.cubic_smoothing = o.smoothing;
    settings.one_sided_outlines = o.one_sided;
    settings.cluster_culling = o.cluster_culling;
    // A one-off frame measures nothing: it uses the machine's kept crossing, if any.
    const LineMethodProfile line_methods = user_line_method_profile(Calibration::kept_only);
    settings.auto_compute_from_triangles = line_methods.threshold();
    if (o.repeat > 0) std::fprintf(stdout, "%s\n", line_methods.describe().c_str());
    render::Renderer renderer(settings, o.camera.size.x, o.camera.size.y,
                              o.repeat > 0 ? gl::TimingMethod::cpu_finish : gl::TimingMethod::off);
    std::vector<std::vector<gl::PassTime>> timings;
    const int frames = std::max(o.repeat, 1) + (o.repeat > 0 ? 2 : 0);  // 2 warm-up frames
    scene::PresentationClock clock;  // --repeat: one nominal 60 Hz frame per picture
    for (int i = 0; i < frames; ++i) {
        clock.advance_nominal();
        clock.stamp(frame);
        renderer.render(frame, meshes, render::Renderer::kOffscreen);
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
        std::fprintf(
            stdout, "%s\n",
            export_frame_svg(o.svg, frame, meshes, o.camera.size.x, o.camera.size.y).c_str());
    }
    print_timings(renderer, timings);
    if (context->debug().error_count() > 0) {
        std::fprintf(stderr, "beamzone render: %d OpenGL error(s) reported\n",
                     context->debug().error_count());
        return 1;
    }
    return 0;
}

}  // namespace bz::app
