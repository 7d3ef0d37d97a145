#pragma once
// Subcommands of build/beamzone. Each lives in its own cmd_<name>.cpp and returns the process
// exit code: 0 ok, 1 bad input (a message was printed), 2 usage error.
#include <span>
#include <string_view>

#include "cli/cli_args.h"

namespace bz::app {

struct Command {
    std::string_view name;
    std::string_view summary;
    int (*run)(Args args);
};

// The table of subcommands, in the order `beamzone --help` lists them.
std::span<const Command> commands();
int dispatch(int argc, char** argv);

int cmd_render(Args args);
int cmd_check(Args args);
int cmd_replay(Args args);
int cmd_play(Args args);
int cmd_bench(Args args);
int cmd_reference(Args args);
int cmd_compare(Args args);
int cmd_difficulty(Args args);

}  // namespace bz::app
