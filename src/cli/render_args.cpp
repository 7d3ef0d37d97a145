#include "cli/render_args.h"

#include "core/budgets.h"
#include "core/error.h"
#include "core/text/printable.h"
#include "scene/style_table.h"

namespace bz::app {

const std::string& render_usage() {
    static const std::string text =
        std::string(
            "usage: beamzone render INPUT [--eye x,y,z] [--target x,y,z] [--up x,y,z] [--fov DEG]\n"
            "                       [--near N] [--far F] [--size WxH] [--preset "
            "fast|balanced|high]\n"
            "                       [--line-method compute|geometry_shader|auto|image_outline]\n"
            "                       [--style NAME] [--shading flat|smooth] [--no-smoothing] "
            "[--one-sided]\n"
            "                       [--color r,g,b] [--out frame.png]\n"
            "                       [--mask mask.png] [--repeat N] [--copies N] [--copy-step F] "
            "[--beam "
            "classic|mame]\n"
            "                       [--lit-share] [--no-cluster-culling] [--hiz-culling]\n"
            "                       [--prepass-raster auto|pipeline|compute] "
            "[--edge-prefilter auto|gpu|cpu]\n"
            "                       [--clears auto|pipeline|compute] "
            "[--bloom-chain auto|pipeline|compute]\n"
            "                       [--material-lines] [--intersection-lines]\n"
            "                       [--svg lines.svg]\n"
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
            "chosen size for timing; the camera frames them all). --copy-step F spaces them F "
            "times\n"
            "the model's size apart (default 1.2; below 1 they overlap, for intersection lines).\n"
            "--beam picks the vector beam's look (default mame, as `play` and `bench`).\n"
            "--no-cluster-culling draws whole meshes in the depth prepass and the fills (the same\n"
            "picture; for timing what culling triangle clusters saves).\n"
            "--hiz-culling skips the edge clusters the depth prepass hides whole (hierarchical-Z;\n"
            "the same picture; off by default, as it did not pay where measured).\n"
            "--prepass-raster: who rasterises the depth prepass's small triangles: a compute "
            "shader\n"
            "on every thread, or the GL pipeline (auto: compute on a software rasteriser for a "
            "dense\n"
            "mesh; the same depth up to float rounding).\n"
            "--edge-prefilter: who rules out the edges that cannot be feature edges before the "
            "edge\n"
            "shader classifies the rest: the CPU, or none (auto: the CPU on a software "
            "rasteriser;\n"
            "the same lines).\n"
            "--clears: who clears the frame's colour images: the GL pipeline (glClear), or a "
            "compute\n"
            "shader, past a GPU's raster back end (auto: glClear on a software rasteriser; on a "
            "GPU\n"
            "both timed at the frame's size, the faster kept and printed; the same pixels).\n"
            "--bloom-chain: who computes the mame beam's bloom levels past the first: one draw "
            "per\n"
            "level each way, or one compute dispatch for the small ones (auto: compute on a "
            "software\n"
            "rasteriser, where each draw costs more than its texels; the same glow up to "
            "rounding).\n"
            "--material-lines draws the edges between faces of different materials as lines too\n"
            "(a model whose parts have their own materials; a level's [render] material_lines).\n"
            "--intersection-lines draws where surfaces cross as lines too: two objects (--copies\n"
            "close enough to overlap) or a model's own parts (a level's [render]\n"
            "intersection_lines).\n"
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

RenderOptions parse_render_args(Args args) {
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
        else if (a == "--repeat")
            o.repeat = parse_int(a, cur.value(a), 1, 100000);
        else if (a == "--copies")
            o.copies = parse_int(a, cur.value(a), 1, budget::kRenderCopies);
        else if (a == "--copy-step") {
            o.copy_step = parse_number(a, cur.value(a));
            if (!(o.copy_step >= 0.05 && o.copy_step <= 100.0))
                throw UsageError("--copy-step must be between 0.05 and 100");
        } else if (a == "--beam")
            o.beam = cur.value(a);
        else if (a == "--svg")
            o.svg = cur.value(a);
        else if (a == "--lit-share")
            o.lit_share = true;
        else if (a == "--no-cluster-culling")
            o.cluster_culling = false;
        else if (a == "--hiz-culling")
            o.hiz_culling = true;
        else if (a == "--material-lines")
            o.material_lines = true;
        else if (a == "--intersection-lines")
            o.intersection_lines = true;
        else if (a == "--overwrite")
            o.overwrite = true;
        else if (a == "--style") {
            o.style = parse_style(a, cur.value(a));
        } else if (a == "--no-smoothing") {
            o.smoothing = false;
        } else if (a == "--one-sided") {
            o.one_sided = true;
        } else if (a == "--prepass-raster") {
            o.prepass_raster = parse_prepass_raster(a, cur.value(a));
        } else if (a == "--edge-prefilter") {
            o.edge_prefilter = parse_edge_prefilter(a, cur.value(a));
        } else if (a == "--clears") {
            o.colour_clears = parse_colour_clears(a, cur.value(a));
        } else if (a == "--bloom-chain") {
            o.bloom_chain = parse_bloom_chain(a, cur.value(a));
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
    try {  // an unknown preset, beam or line method is a usage error
        render::preset(o.preset);
        render::beam_look(o.beam);
        if (!o.line_method.empty()) render::parse_line_method(o.line_method);
    } catch (const UserError& e) {
        throw UsageError(e.what());
    }
    return o;
}

}  // namespace bz::app
