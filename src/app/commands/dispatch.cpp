#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "app/commands/commands.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/text/printable.h"

namespace bz::app {

namespace {

constexpr Command kCommands[] = {
    {"play", "play the game in a window (F11 fullscreen, F12 screenshot, --help for keys)",
     cmd_play},
    {"render", "render a model file headless to PNG (and a line mask)", cmd_render},
    {"check", "validate level files (file:line:col errors), no window needed", cmd_check},
    {"replay", "inspect a replay file, or --verify it headless against its state hashes",
     cmd_replay},
    {"bench", "frame-time benchmark of a level offscreen; --sweep: speed vs accuracy", cmd_bench},
    {"reference", "exact CPU line mask of a model or a level frame (same format as render --mask)",
     cmd_reference},
    {"compare", "precision, recall and F1 of a line mask against a reference mask", cmd_compare},
    {"difficulty", "the difficulty table: time to first death per level and difficulty, headless",
     cmd_difficulty},
};

void print_usage(std::FILE* out) {
    std::fprintf(out, "usage: beamzone <command> [options]\n\ncommands:\n");
    for (const auto& c : kCommands) {
        std::fprintf(out, "  %-10.*s %.*s\n", static_cast<int>(c.name.size()), c.name.data(),
                     static_cast<int>(c.summary.size()), c.summary.data());
    }
    std::fprintf(out, "\n'beamzone <command> --help' describes one command.\n");
}

}  // namespace

std::span<const Command> commands() {
    return kCommands;
}

int dispatch(int argc, char** argv) {
    install_interrupt_handlers();  // before anything starts SDL (see core/interrupt.h)
    if (argc < 2) {
        print_usage(stderr);
        return 2;
    }
    const std::string_view name = argv[1];
    if (name == "--help" || name == "-h" || name == "help") {
        print_usage(stdout);
        return 0;
    }
    if (name == "--version") {
        std::printf("beamzone %s\n", BEAMZONE_VERSION);
        return 0;
    }
    for (const auto& c : kCommands) {
        if (c.name != name) continue;
        try {
            return c.run(Args(argv + 2, static_cast<std::size_t>(argc - 2)));
        } catch (const UserError& e) {
            std::fprintf(stderr, "beamzone: error: %s\n", printable_message(e.what()).c_str());
            return 1;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "beamzone: internal error: %s\n",
                         printable_message(e.what()).c_str());
            return 1;
        }
    }
    std::fprintf(stderr, "beamzone: unknown command '%s'\n", printable(argv[1]).c_str());
    print_usage(stderr);
    return 2;
}

}  // namespace bz::app
