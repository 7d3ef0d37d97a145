#pragma once
// The part every subcommand shares: `--help` prints the usage (exit 0), a bad command line
// prints one line naming the command and the problem, then the usage (exit 2).
#include <cstdio>
#include <optional>
#include <string_view>

#include "app/commands/commands.h"
#include "cli/cli_args.h"
#include "core/text/printable.h"

namespace bz::app {

// Returns the parsed options, or nothing with *exit_code set to what main should return.
template <class Parse>
auto parse_command(std::string_view name, Args args, const char* usage, Parse parse, int* exit_code)
    -> std::optional<decltype(parse(args))> {
    for (const char* a : args) {
        if (std::string_view(a) == "--help" || std::string_view(a) == "-h") {
            std::fputs(usage, stdout);
            *exit_code = 0;
            return std::nullopt;
        }
    }
    try {
        return parse(args);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "beamzone %.*s: %s\n%s", static_cast<int>(name.size()), name.data(),
                     printable_message(e.what()).c_str(), usage);
        *exit_code = 2;
        return std::nullopt;
    }
}

}  // namespace bz::app
