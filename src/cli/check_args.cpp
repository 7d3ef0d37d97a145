#include "cli/check_args.h"

#include "core/text/printable.h"

namespace bz::app {

const char* const kCheckUsage =
    "usage: beamzone check [--quiet] FILE...\n"
    "Validates level files without opening a window, and imports every model a level names\n"
    "with the same importer and limits as play. Every problem is printed to stderr as\n"
    "'file:line:col: error: message'; a clean file prints one 'ok' line to stdout unless\n"
    "--quiet. Exit status: 0 all clean, 1 some file has errors, 2 usage error.\n";

CheckOptions parse_check_args(Args args) {
    CheckOptions o;
    bool options_done = false;
    for (const char* arg : args) {
        const std::string_view a = arg;
        if (!options_done && a == "--") {
            options_done = true;
        } else if (!options_done && (a == "--quiet" || a == "-q")) {
            o.quiet = true;
        } else if (!options_done && a.size() > 1 && a[0] == '-') {
            throw UsageError("unknown option '" + printable(a) + "'");
        } else {
            o.files.push_back(a);
        }
    }
    if (o.files.empty()) throw UsageError("no level files given");
    return o;
}

}  // namespace bz::app
