#pragma once
// The command line of `beamzone replay`: parsed and checked without a model, a level or GL, so
// the fuzz target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <cstdint>
#include <optional>
#include <string>

#include "cli/cli_args.h"
#include "game/difficulty/difficulty.h"

namespace bz::app {

extern const char* const kReplayUsage;  // the --help text

struct ReplayOptions {
    std::string file;
    std::string level;
    bool verify = false;
    bool inputs_only = false;  // --verify without requiring state hashes
    int record_seconds = 0;
    std::uint64_t seed = 1;
    std::optional<level::Difficulty> difficulty;
    bool overwrite = false;  // --record-demo may replace a file that is not a replay
};

// Throws UsageError naming the bad option.
ReplayOptions parse_replay_args(Args args);

}  // namespace bz::app
