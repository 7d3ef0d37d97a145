// beamzone compare TEST.png REF.png [--tol PX]: precision, recall and F1 of a line mask
// against a reference mask, lit pixels matched within a pixel tolerance.
#include <cstdio>
#include <string>

#include "app/commands/cli_args.h"
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/text/printable.h"
#include "geometry/reference/mask_score.h"

namespace bz::app {

namespace {

constexpr const char* kUsage =
    "usage: beamzone compare TEST.png REF.png [--tol PX] [--ink]\n"
    "Scores a line mask (e.g. 'render --mask') against a reference mask (e.g. 'reference'):\n"
    "  precision  lit TEST pixels with a lit REF pixel within PX pixels (Chebyshev distance)\n"
    "  recall     lit REF pixels with a lit TEST pixel within PX pixels\n"
    "  f1         2 * precision * recall / (precision + recall)\n"
    "A pixel is lit when its gray value is at least 128. --tol defaults to 1. Both images\n"
    "must have the same size.\n"
    "--ink: TEST is a frame of a paper style, whose lines are dark ink: its pixels darker\n"
    "than gray 110 count as lit (the halo style's recall of the exact visible lines).\n";

struct Options {
    std::string test, ref;
    int tol = 1;
    bool ink = false;
};

Options parse(Args args) {
    Options o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (a == "--tol") {
            o.tol = parse_int(a, cur.value(a), 0, 64);
        } else if (a == "--ink") {
            o.ink = true;
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else if (o.test.empty()) {
            o.test = a;
        } else if (o.ref.empty()) {
            o.ref = a;
        } else {
            throw UsageError("expected two images, got a third: " + printable(a));
        }
    }
    if (o.ref.empty()) throw UsageError("need TEST.png and REF.png");
    return o;
}

std::vector<std::uint8_t> lit_pixels(const Image& img, bool ink = false) {
    std::vector<std::uint8_t> out(img.pixels.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = (ink ? img.pixels[i] < 110 : img.pixels[i] >= 128) ? 1 : 0;
    return out;
}

}  // namespace

int cmd_compare(Args args) {
    int exit_code = 0;
    const std::optional<Options> parsed = parse_command("compare", args, kUsage, parse, &exit_code);
    if (!parsed) return exit_code;
    const Options& o = *parsed;
    const Image test = read_png(o.test, 1);
    const Image ref = read_png(o.ref, 1);
    if (test.width != ref.width || test.height != ref.height) {
        throw UserError(o.test + " is " + std::to_string(test.width) + "x" +
                        std::to_string(test.height) + " but " + o.ref + " is " +
                        std::to_string(ref.width) + "x" + std::to_string(ref.height) +
                        ": masks must have the same size");
    }
    const geo::MaskScore s =
        geo::score_masks(lit_pixels(test, o.ink), lit_pixels(ref), test.width, test.height, o.tol);
    std::printf(
        "precision %.4f recall %.4f f1 %.4f (test %zu lit, reference %zu lit, tolerance %d px)\n",
        s.precision, s.recall, s.f1, s.test_lit, s.ref_lit, o.tol);
    return 0;
}

}  // namespace bz::app
