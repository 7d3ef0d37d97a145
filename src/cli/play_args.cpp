#include "cli/play_args.h"

#include <algorithm>
#include <charconv>

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
                                 printable(m) + "'");
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

}  // namespace bz::app
