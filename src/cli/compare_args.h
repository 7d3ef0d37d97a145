#pragma once
// The command line of `beamzone compare`: parsed and checked without a model, a level or GL, so
// the fuzz target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <string>

#include "cli/cli_args.h"

namespace bz::app {

extern const char* const kCompareUsage;  // the --help text

struct CompareOptions {
    std::string test, ref;
    int tol = 1;
    bool ink = false;
};

// Throws UsageError naming the bad option.
CompareOptions parse_compare_args(Args args);

}  // namespace bz::app
