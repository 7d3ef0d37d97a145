#pragma once
// The command line of `beamzone difficulty`: parsed and checked without a model, a level or GL, so
// the fuzz target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "game/difficulty/difficulty.h"

namespace bz::app {

extern const char* const kDifficultyUsage;  // the --help text

struct DifficultyOptions {
    std::vector<std::string> levels;
    int seeds = 20;
    double seconds = 120.0;
    std::vector<game::Difficulty> difficulties{game::Difficulty::easy, game::Difficulty::normal,
                                               game::Difficulty::arcade};
    std::string json;
    bool overwrite = false;  // --json may replace an existing file that is not JSON
};

// Throws UsageError naming the bad option.
DifficultyOptions parse_difficulty_args(Args args);

}  // namespace bz::app
