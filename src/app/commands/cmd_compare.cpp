// beamzone compare TEST.png REF.png [--tol PX]: precision, recall and F1 of a line mask
// against a reference mask, lit pixels matched within a pixel tolerance.
#include <cstdio>
#include <string>

#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "cli/compare_args.h"
#include "core/error.h"
#include "core/image_io.h"
#include "core/text/printable.h"
#include "geometry/reference/mask_score.h"

namespace bz::app {

namespace {

std::vector<std::uint8_t> lit_pixels(const Image& img, bool ink = false) {
    std::vector<std::uint8_t> out(img.pixels.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = (ink ? img.pixels[i] < 110 : img.pixels[i] >= 128) ? 1 : 0;
    return out;
}

}  // namespace

int cmd_compare(Args args) {
    int exit_code = 0;
    const std::optional<CompareOptions> parsed =
        parse_command("compare", args, kCompareUsage, parse_compare_args, &exit_code);
    if (!parsed) return exit_code;
    const CompareOptions& o = *parsed;
    const Image test = read_png(o.test, 1);
    const Image ref = read_png(o.ref, 1);
    if (test.width != ref.width || test.height != ref.height) {
        throw UserError(printable(o.test) + " is " + std::to_string(test.width) + "x" +
                        std::to_string(test.height) + " but " + printable(o.ref) + " is " +
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
