#include "cli/reference_args.h"

#include "core/text/printable.h"

namespace bz::app {

const char* const kReferenceUsage =
    "usage: beamzone reference INPUT [--eye x,y,z] [--target x,y,z] [--up x,y,z] [--fov DEG]\n"
    "                          [--near N] [--far F] [--size WxH] [--style NAME]\n"
    "                          [--crease DEG] [--material-lines] [--intersection-lines]\n"
    "                          [--mask ref.png] [--svg lines.svg] [--overwrite]\n"
    "       beamzone reference --level LEVEL.toml --time SECONDS [--size WxH] [--mask ref.png]\n"
    "                          [--svg lines.svg]\n"
    "Computes the exact line mask on the CPU in double precision: the geometry shader's\n"
    "feature edges, visibility by ray casting against every occluder triangle at sub-pixel\n"
    "samples. Same camera options and mask format as 'render --mask' (255 = line, row 0 at\n"
    "the top). INPUT is a model file or builtin:cube, builtin:sphere, builtin:grid.\n"
    "--level puts the camera on the level's benchmark path at --time (the frame 'bench'\n"
    "renders at that simulated time, at the game's 45 degree field of view).\n"
    "--crease sets the crease angle (default 60, the renderer's).\n"
    "--material-lines: edges between faces of different materials are lines too (as 'render\n"
    "--material-lines'); a level's [render] material_lines = true turns them on too.\n"
    "--intersection-lines: where two surfaces cross, a line (as 'render --intersection-lines');\n"
    "a level's [render] intersection_lines = true turns them on too.\n"
    "--svg also writes the same visible lines as SVG (see 'render --svg').\n";

ReferenceOptions parse_reference_args(Args args) {
    ReferenceOptions o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (parse_camera_option(a, cur, o.camera)) continue;
        if (a == "--level") {
            o.level = cur.value(a);
        } else if (a == "--time") {
            o.time = parse_number(a, cur.value(a));
        } else if (a == "--crease") {
            o.crease = parse_number(a, cur.value(a));
        } else if (a == "--mask" || a == "--out") {
            o.mask = cur.value(a);
        } else if (a == "--svg") {
            o.svg = cur.value(a);
        } else if (a == "--material-lines") {
            o.material_lines = true;
        } else if (a == "--intersection-lines") {
            o.intersection_lines = true;
        } else if (a == "--overwrite") {
            o.overwrite = true;
        } else if (a == "--style") {
            o.style = parse_style(a, cur.value(a));
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else if (o.input.empty()) {
            o.input = a;
        } else {
            throw UsageError("more than one INPUT given");
        }
    }
    if (o.level.empty()) {
        if (o.input.empty()) throw UsageError("no INPUT model given (or --level LEVEL --time T)");
        if (o.time) throw UsageError("--time needs --level");
        validate_camera(o.camera);
    } else {
        if (!o.input.empty()) throw UsageError("give either INPUT or --level, not both");
        if (!o.time) throw UsageError("--level needs --time SECONDS");
        if (*o.time < 0.0 || *o.time > 3600.0) throw UsageError("--time must be in [0, 3600]");
        if (o.camera.any_view_option)
            throw UsageError("--level takes its camera from the level's path: only --size applies");
    }
    if (!(o.crease > 0.0 && o.crease <= 180.0)) throw UsageError("--crease must be in (0, 180]");
    if (!o.svg.empty() && o.svg == o.mask) throw UsageError("--svg and --mask name the same file");
    return o;
}

}  // namespace bz::app
