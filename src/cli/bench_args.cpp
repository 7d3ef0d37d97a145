#include "cli/bench_args.h"

#include "core/error.h"
#include "core/text/printable.h"
#include "render/settings.h"

namespace bz::app {

namespace {

// An unknown preset, line method or beam name is a usage error.
void check_names(const BenchOptions& o) {
    try {
        if (!o.preset.empty()) render::preset(o.preset);
        if (!o.line_method.empty()) render::parse_line_method(o.line_method);
        if (!o.beam.empty()) render::beam_look(o.beam);
    } catch (const UserError& e) {
        throw UsageError(e.what());
    }
}

}  // namespace

const char* const kBenchUsage =
    "usage: beamzone bench LEVEL [--frames N] [--warmup N] [--size WxH]\n"
    "                      [--preset fast|balanced|high] [--style NAME] [--sweep | --scaling]\n"
    "                      [--line-method compute|geometry_shader|auto|image_outline]\n"
    "                      [--out DIR] [--replay FILE] [--samples N] [--rounds N]\n"
    "                      [--timing auto|cpu|gpu] [--beam classic|mame] [--no-phosphor]\n"
    "                      [--clears auto|pipeline|compute] [--prepass-raster "
    "auto|pipeline|compute]\n"
    "                      [--edge-prefilter auto|gpu|cpu] [--bloom-chain "
    "auto|pipeline|compute]\n"
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
    "--clears picks who clears the frame's colour images (not with --sweep): the GL pipeline\n"
    "or a compute shader (auto: glClear on a software rasteriser; on a GPU both timed at the\n"
    "frame's size and the faster kept; the same pixels). summary.json gives the path and times.\n"
    "--prepass-raster, --edge-prefilter and --bloom-chain as for `render` (see `render "
    "--help`;\n"
    "not with --sweep): the same frames, other work.\n"
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

BenchOptions parse_bench_args(Args args) {
    BenchOptions o;
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
            const BenchMode m = a == "--sweep"     ? BenchMode::sweep
                                : a == "--scaling" ? BenchMode::scaling
                                                   : BenchMode::accuracy;
            if (o.mode != BenchMode::single && o.mode != m)
                throw UsageError("--sweep, --scaling and --accuracy exclude each other");
            o.mode = m;
        } else if (a == "--beam") {
            o.beam = cur.value(a);
        } else if (a == "--no-phosphor") {
            o.no_phosphor = true;
        } else if (a == "--clears") {
            o.colour_clears = parse_colour_clears(a, cur.value(a));
        } else if (a == "--prepass-raster") {
            o.prepass_raster = parse_prepass_raster(a, cur.value(a));
        } else if (a == "--edge-prefilter") {
            o.edge_prefilter = parse_edge_prefilter(a, cur.value(a));
        } else if (a == "--bloom-chain") {
            o.bloom_chain = parse_bloom_chain(a, cur.value(a));
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
    if (o.mode == BenchMode::accuracy) {
        check_names(o);
        if (!o.level.empty()) throw UsageError("--accuracy takes no LEVEL (it draws models)");
        if (preset_given) throw UsageError("--preset and --accuracy exclude each other");
        if (!o.replay.empty()) throw UsageError("--replay and --accuracy exclude each other");
        if (o.no_phosphor) throw UsageError("--no-phosphor and --accuracy exclude each other");
        if (o.colour_clears || o.prepass_raster || o.edge_prefilter || o.bloom_chain)
            throw UsageError(
                "--clears, --prepass-raster, --edge-prefilter and --bloom-chain exclude --accuracy "
                "(it times every preset as it is)");
        if (!o.frames_given) o.frames = 6;
        if (!o.size_given) o.size = {640, 480};
        if (o.out.empty()) throw UsageError("--out needs a directory");
        return o;
    }
    if (!o.models.empty()) throw UsageError("--model needs --accuracy");
    if (o.level.empty()) throw UsageError("no LEVEL given");
    if (preset_given && o.mode == BenchMode::sweep)
        throw UsageError("--preset and --sweep exclude each other (the sweep runs every preset)");
    if (!o.line_method.empty() && o.mode == BenchMode::sweep)
        throw UsageError(
            "--line-method and --sweep exclude each other (the sweep runs every method)");
    if (o.style && o.mode == BenchMode::sweep)
        throw UsageError("--style and --sweep exclude each other (the sweep runs every style)");
    if (o.no_phosphor && o.mode == BenchMode::sweep)
        throw UsageError(
            "--no-phosphor and --sweep exclude each other (the sweep sets every look)");
    if ((o.colour_clears || o.prepass_raster || o.edge_prefilter || o.bloom_chain) &&
        o.mode == BenchMode::sweep)
        throw UsageError(
            "--clears, --prepass-raster, --edge-prefilter and --bloom-chain exclude --sweep (the "
            "sweep times every configuration as it is)");
    if (o.mode == BenchMode::scaling && !o.frames_given) o.frames = 40;
    // Seven configurations: fewer frames each keep a sweep on llvmpipe within minutes.
    if (o.mode == BenchMode::sweep && !o.frames_given) o.frames = 240;
    if (o.out.empty()) throw UsageError("--out needs a directory");
    check_names(o);
    return o;
}

}  // namespace bz::app
