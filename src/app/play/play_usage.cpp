#include "app/play/play_usage.h"

#include <algorithm>
#include <cctype>

#include "app/play/menu/play_menus.h"
#include "core/text/printable.h"
#include "scene/style_table.h"

namespace bz::app {

namespace {

// Every action with its default keys, two to a line, generated from the bindings so that
// a key added there is never missing here.
std::string key_table() {
    const platform::Bindings keys = platform::default_bindings();
    std::string out;
    std::string line = " ";
    for (std::size_t i = 0; i < platform::kActionCount; ++i) {
        const auto a = static_cast<platform::Action>(i);
        std::string label = menu::action_label(a);
        for (char& c : label) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        const std::string entry = label + ": " + platform::keys_label(keys, a, 4);
        if (line.size() + entry.size() + 3 > 88) {
            out += line + "\n";
            line = " ";
        }
        line += (line.size() > 1 ? ";  " : " ") + entry;
    }
    return out + line + "\n";
}

}  // namespace

std::string play_usage(const std::string& settings_path, const std::string& high_scores_path) {
    return "usage: beamzone play [LEVEL] [--edit] [--preset fast|balanced|high]\n"
           "                     [--style NAME] [--beam mame|classic]\n"
           "                     [--windowed|--fullscreen]\n"
           "                     [--vsync off|on|adaptive] [--record FILE] [--replay FILE]\n"
           "                     [--seed N] [--size WxH] [--frames N] [--screenshot-at N]\n"
           "                     [--press FRAME:KEY,...] [--difficulty easy|normal|arcade]\n"
           "                     [--headless-test]\n"
           "Plays LEVEL (default levels/classic.toml) in a window. Edits to the level file are\n"
           "picked up while playing; errors show on screen and the last good level stays.\n"
           "  --edit           fly around the level without gameplay (WASD, R/F up/down,\n"
           "                   arrows or right mouse button to look, Shift faster)\n"
           "  --style S        style for this run (else the level's, else the settings'):\n" +
           scene::style_help() +
           "  --beam B         vector beam look, mame or classic (else the settings', else the\n"
           "                   level's, else mame)\n"
           "  --preset P       render preset for this run (else the settings', else the level's)\n"
           "  --difficulty D   for this run (else the settings' `difficulty`, else the level's)\n"
           "  --line-method M  compute, geometry_shader or auto, for this run (else the "
           "settings',\n"
           "                   else the level's, else the preset's)\n"
           "  --record FILE    save this game's inputs so --replay FILE plays it back exactly\n"
           "                   (until the level file changes: a replay belongs to one level)\n"
           "  --seed N         random seed of the game (default: from the clock)\n"
           "  --size WxH       window size (default 1280x720; 640x360 for --headless-test)\n"
           "  --frames N       run N frames, one 60 Hz tick each, then exit (for tests)\n"
           "  --screenshot-at N  save a screenshot after frame N, as F12 does\n"
           "  --press F:KEY,... tap KEY before frame F (e.g. 2:Down,3:Return opens Level);\n"
           "                   F-G:KEY holds it from frame F to frame G\n"
           "  --headless-test  run in a hidden window, e.g. with SDL_VIDEODRIVER=offscreen\n"
           "                   (BEAMZONE_ALLOW_OFFSCREEN=1 does the same)\n"
           "Keys (rebind them in game under Options > Keys, or in the settings file):\n" +
           key_table() +
           "Menus: arrows choose, Enter selects, Backspace or Esc back; the mouse works too\n"
           "(hover selects, click chooses, the wheel scrolls, the right button goes back).\n"
           "Game controllers: sticks drive the treads (or the left stick alone: gamepad =\n"
           "\"drive\" in the settings), triggers, A or R1 fire, Start pauses or starts, B back;\n"
           "buttons are rebound under Options > Keys too (press a pad button), and the menus\n"
           "always take the d-pad, A, B and Start.\n"
           "\n"
           "settings:    " +
           settings_path +
           "\n"
           "high scores: " +
           high_scores_path + "\n";
}

}  // namespace bz::app
