#include "cli/replay_args.h"

#include "core/text/printable.h"

namespace bz::app {

const char* const kReplayUsage =
    "usage: beamzone replay FILE [--verify [--inputs-only]] [--level LEVEL.toml]\n"
    "       beamzone replay FILE --record-demo SECONDS [--seed N] [--level LEVEL.toml]\n"
    "                                             [--difficulty easy|normal|arcade] [--overwrite]\n"
    "Prints what a replay file holds. --verify re-simulates it headless (no window) from its\n"
    "seed and commands and checks every recorded state hash: exit 0 when all match, 1 with\n"
    "the first mismatching tick. A replay without a state hash at every hash interval and at\n"
    "its last tick is refused (nothing would prove it); --inputs-only re-simulates it anyway,\n"
    "checking only the hashes it has. --level overrides the level file the replay names.\n"
    "--record-demo writes FILE: the attract-mode autopilot playing for SECONDS, headless\n"
    "(the built-in level unless --level is given), at the level's difficulty unless\n"
    "--difficulty is given.\n";

ReplayOptions parse_replay_args(Args args) {
    ReplayOptions o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (a == "--verify") {
            o.verify = true;
        } else if (a == "--inputs-only") {
            o.inputs_only = true;
        } else if (a == "--level") {
            o.level = cur.value(a);
        } else if (a == "--overwrite") {
            o.overwrite = true;
        } else if (a == "--record-demo") {
            o.record_seconds = parse_int(a, cur.value(a), 1, 10 * 3600);
        } else if (a == "--seed") {
            o.seed = static_cast<std::uint64_t>(parse_int(a, cur.value(a), 0, 2147483647));
        } else if (a == "--difficulty") {
            const std::string_view v = cur.value(a);
            o.difficulty = game::parse_difficulty(v);
            if (!o.difficulty) {
                throw UsageError("--difficulty must be one of " +
                                 std::string(game::kDifficultyNames) + ", not '" + printable(v) +
                                 "'");
            }
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else if (o.file.empty()) {
            o.file = a;
        } else {
            throw UsageError("more than one replay FILE given");
        }
    }
    if (o.file.empty()) throw UsageError("no replay FILE given");
    if (o.inputs_only && !o.verify) throw UsageError("--inputs-only needs --verify");
    if (o.verify && o.record_seconds > 0)
        throw UsageError("--verify and --record-demo exclude each other");
    return o;
}

}  // namespace bz::app
