#include "cli/difficulty_args.h"

#include "core/paths.h"
#include "core/text/printable.h"

namespace bz::app {

const char* const kDifficultyUsage =
    "usage: beamzone difficulty [LEVEL...] [--seeds N] [--seconds S]\n"
    "                           [--difficulty easy|normal|arcade] [--json FILE] [--overwrite]\n"
    "Plays N games (default 20, seeds 1..N) per level and difficulty headless and prints, as a\n"
    "Markdown table, the mean time to the first death of an idle player and of the autopilot\n"
    "(games still alive after S seconds, default 120, count as S; 'alive' says how many), and\n"
    "the share of enemies that appeared in the 90 degrees behind the player. Without LEVEL,\n"
    "every shipped level that has enemies. --json writes the same numbers as JSON (an existing\n"
    "file there must be JSON unless --overwrite is given).\n";

DifficultyOptions parse_difficulty_args(Args args) {
    DifficultyOptions o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    bool difficulty_given = false;
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (a == "--seeds") {
            o.seeds = parse_int(a, cur.value(a), 1, 10000);
        } else if (a == "--seconds") {
            o.seconds = parse_number(a, cur.value(a));
            if (!(o.seconds > 0.0 && o.seconds <= 3600.0))
                throw UsageError("--seconds must be more than 0 and at most 3600");
        } else if (a == "--difficulty") {
            const std::string_view v = cur.value(a);
            const auto d = game::parse_difficulty(v);
            if (!d) {
                throw UsageError("--difficulty must be one of " +
                                 std::string(game::kDifficultyNames) + ", not '" + printable(v) +
                                 "'");
            }
            if (!difficulty_given) o.difficulties.clear();
            difficulty_given = true;
            o.difficulties.push_back(*d);
        } else if (a == "--json") {
            o.json = cur.value(a);
        } else if (a == "--overwrite") {
            o.overwrite = true;
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else {
            o.levels.emplace_back(a);
        }
    }
    if (o.levels.empty()) {
        for (const char* name : {"tutorial", "classic", "maze", "volcano_night", "plains"})
            o.levels.push_back((levels_dir() / (std::string(name) + ".toml")).string());
    }
    return o;
}

}  // namespace bz::app
