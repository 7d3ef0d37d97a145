#pragma once
// The command line of `beamzone check`: parsed without a level, a model or GL, so the fuzz
// target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <string_view>
#include <vector>

#include "cli/cli_args.h"

namespace bz::app {

extern const char* const kCheckUsage;  // the --help text

struct CheckOptions {
    std::vector<std::string_view> files;  // into the argument vector
    bool quiet = false;
};

// Throws UsageError for an unknown option or no file. After `--` every word is a file.
CheckOptions parse_check_args(Args args);

}  // namespace bz::app
