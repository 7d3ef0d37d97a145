#include "cli/compare_args.h"

#include "core/text/printable.h"

namespace bz::app {

const char* const kCompareUsage =
    "usage: beamzone compare TEST.png REF.png [--tol PX] [--ink]\n"
    "Scores a line mask (e.g. 'render --mask') against a reference mask (e.g. 'reference'):\n"
    "  precision  lit TEST pixels with a lit REF pixel within PX pixels (Chebyshev distance)\n"
    "  recall     lit REF pixels with a lit TEST pixel within PX pixels\n"
    "  f1         2 * precision * recall / (precision + recall)\n"
    "A pixel is lit when its gray value is at least 128. --tol defaults to 1. Both images\n"
    "must have the same size.\n"
    "--ink: TEST is a frame of a paper style, whose lines are dark ink: its pixels darker\n"
    "than gray 110 count as lit (the halo style's recall of the exact visible lines).\n";

CompareOptions parse_compare_args(Args args) {
    CompareOptions o;
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

}  // namespace bz::app
