#pragma once
// The command line of `beamzone play`, parsed without a window or GL.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_args.h"
#include "platform/bindings.h"
#include "platform/gl_context.h"

namespace bz::app {

// A key pressed before frame `frame` and released before `release_frame` (the same frame: a
// tap shorter than a tick).
struct ScriptedPress {
    int frame = 1;
    int release_frame = 1;
    platform::KeyBinding key;
};

struct PlayOptions {
    std::string level;  // empty: levels/classic.toml, or the game's built-in level
    bool edit = false;
    std::optional<std::string> preset;
    std::optional<std::string> style;        // a style name (scene/style.h)
    std::optional<std::string> beam;         // "mame" or "classic"
    std::optional<std::string> line_method;  // "compute" or "geometry_shader"
    std::optional<bool> fullscreen;          // --fullscreen / --windowed
    std::optional<platform::Vsync> vsync;
    std::string record;
    std::string replay;
    std::optional<std::uint64_t> seed;
    std::optional<std::string> difficulty;  // "easy", "normal" or "arcade"
    std::optional<glm::ivec2> size;  // window size (--size WxH); default 1280x720, tests 640x360
    int frames = 0;                  // > 0: run this many frames (one tick each) and exit
    int screenshot_at = 0;           // > 0: take a screenshot after this frame, as F12 would
    bool headless_test = false;      // run in a hidden window under SDL's offscreen driver
    // --press FRAME:KEY,...: keys tapped before those frames (tests, screenshots of menus).
    std::vector<ScriptedPress> presses;
    bool help = false;
};

// Throws UsageError (cli/cli_args.h) naming the bad option.
PlayOptions parse_play_options(int argc, char* const* argv);

}  // namespace bz::app
