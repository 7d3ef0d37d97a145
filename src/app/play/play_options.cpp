#include "app/play/play_options.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "app/commands/cli_args.h"
#include "app/play/menu/play_menus.h"
#include "core/text/printable.h"
#include "platform/settings.h"
#include "render/settings.h"
#include "scene/style_table.h"

namespace bz::app {

namespace {

std::uint64_t parse_seed(std::string_view option, std::string_view text) {
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (text.empty() || r.ec != std::errc{} || r.ptr != end) {
        throw UsageError(std::string(option) + ": '" + printable(text) +
                         "' is not a whole number from 0 to 18446744073709551615");
    }
    return v;
}

// "30:Down,31:Return,90:Alt+Return,5-9:Up": frame numbers from 1 (a range holds the key from
// the first frame to the last), keys as the settings file names them.
std::vector<ScriptedPress> parse_presses(std::string_view option, std::string_view text) {
    std::vector<ScriptedPress> out;
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        const std::size_t colon = item.find(':');
        if (colon == std::string_view::npos) {
            throw UsageError(std::string(option) + ": '" + printable(item) +
                             "' is not FRAME:KEY (e.g. 30:Return)");
        }
        const std::string_view frames = item.substr(0, colon);
        const std::size_t dash = frames.find('-');
        ScriptedPress p;
        p.frame = parse_int(option, frames.substr(0, dash), 1, 100000000);
        p.release_frame = dash == std::string_view::npos
                              ? p.frame
                              : parse_int(option, frames.substr(dash + 1), p.frame, 100000000);
        std::string why;
        const auto key = platform::parse_key(item.substr(colon + 1), &why);
        if (!key) throw UsageError(std::string(option) + ": " + why);
        p.key = *key;
        out.push_back(p);
    }
    return out;
}

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

PlayOptions parse_play_options(int argc, char* const* argv) {
    PlayOptions o;
    ArgCursor cur(argc, argv);
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--edit") {
            o.edit = true;
        } else if (a == "--preset") {
            const std::string p(cur.value(a));
            const auto& names = render::preset_names();
            if (std::find(names.begin(), names.end(), p) == names.end()) {
                std::string list;
                for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
                throw UsageError("--preset: expected one of " + list + ", not '" + printable(p) +
                                 "'");
            }
            o.preset = p;
        } else if (a == "--line-method") {
            const std::string m(cur.value(a));
            if (m != "compute" && m != "geometry_shader" && m != "auto" && m != "geometry") {
                throw UsageError("--line-method: expected compute, geometry_shader or auto, not '" +
                                 m + "'");
            }
            o.line_method = m;
        } else if (a == "--style") {
            const std::string s(cur.value(a));
            if (!scene::style_from_name(s)) {
                throw UsageError("--style: expected " + scene::style_name_list() + ", not '" +
                                 printable(s) + "'");
            }
            o.style = s;
        } else if (a == "--beam") {
            const std::string b(cur.value(a));
            if (b != "mame" && b != "classic") {
                throw UsageError("--beam: expected mame or classic, not '" + printable(b) + "'");
            }
            o.beam = b;
        } else if (a == "--difficulty") {
            const std::string d(cur.value(a));
            if (d != "easy" && d != "normal" && d != "arcade") {
                throw UsageError("--difficulty: expected easy, normal or arcade, not '" +
                                 printable(d) + "'");
            }
            o.difficulty = d;
        } else if (a == "--windowed") {
            o.fullscreen = false;
        } else if (a == "--fullscreen") {
            o.fullscreen = true;
        } else if (a == "--vsync") {
            const std::string_view v = cur.value(a);
            platform::Vsync mode{};
            if (!platform::parse_vsync(v, &mode)) {
                throw UsageError("--vsync: expected off, on or adaptive, not '" + printable(v) +
                                 "'");
            }
            o.vsync = mode;
        } else if (a == "--record") {
            o.record = cur.value(a);
        } else if (a == "--replay") {
            o.replay = cur.value(a);
        } else if (a == "--seed") {
            o.seed = parse_seed(a, cur.value(a));
        } else if (a == "--size") {
            o.size = parse_size(a, cur.value(a));
        } else if (a == "--frames") {
            o.frames = parse_int(a, cur.value(a), 1, 100000000);
        } else if (a == "--screenshot-at") {
            o.screenshot_at = parse_int(a, cur.value(a), 1, 100000000);
        } else if (a == "--press") {
            const auto more = parse_presses(a, cur.value(a));
            o.presses.insert(o.presses.end(), more.begin(), more.end());
        } else if (a == "--headless-test") {
            o.headless_test = true;
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a) + " (see beamzone play --help)");
        } else if (o.level.empty()) {
            o.level = a;
        } else {
            throw UsageError("more than one LEVEL given");
        }
    }
    if (!o.record.empty() && !o.replay.empty()) {
        throw UsageError("--record and --replay cannot be used together");
    }
    if (o.edit && (!o.record.empty() || !o.replay.empty())) {
        throw UsageError("--edit views a level; it cannot --record or --replay");
    }
    return o;
}

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
           "\"drive\" in the settings), triggers, A or R1 fire, Start pauses or starts, B back.\n"
           "\n"
           "settings:    " +
           settings_path +
           "\n"
           "high scores: " +
           high_scores_path + "\n";
}

}  // namespace bz::app
