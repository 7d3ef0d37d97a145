#include "platform/settings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <utility>

#include "core/budgets.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/text/printable.h"
#include "core/text/toml.h"
#include "core/text/toml_scan.h"

namespace bz::platform {

namespace {

// Settings are a few hundred bytes; anything this large is not a settings file.
constexpr std::size_t kMaxSettingsBytes = budget::kSettingsBytes;
// toml++ recurses once per level of a dotted key, so a key thousands of levels deep overflows
// the stack; the deepest real setting is keys.fire. Refused before parsing, as levels do.
constexpr int kMaxSettingsKeyDots = 8;
// As for levels: a generated file full of junk should not print forever.
constexpr std::size_t kMaxSettingsErrors = 100;

std::string located(const std::string& source, std::size_t line, std::size_t column,
                    const std::string& message) {
    return source + ":" + std::to_string(line) + ":" + std::to_string(column) +
           ": error: " + message;
}

// 1-based line and column of a byte offset.
std::pair<std::size_t, std::size_t> position_of(std::string_view text, std::size_t offset) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return {line, column};
}

// What toml++ must not be given (see core/text/toml_scan.h), as one positioned message.
std::optional<std::string> unsafe_toml(std::string_view text, const std::string& source) {
    if (const auto deep = find_deep_key(text, kMaxSettingsKeyDots)) {
        std::size_t at = deep->offset;
        while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
        const auto [line, column] = position_of(text, at);
        return located(source, line, column,
                       "key is nested more than " + std::to_string(kMaxSettingsKeyDots) +
                           " levels deep (too many dots)");
    }
    if (const auto bad = find_unsafe_char(text)) {
        const auto [line, column] = position_of(text, bad->offset);
        return located(source, line, column, std::string("syntax error: ") + bad->why);
    }
    return std::nullopt;
}

class Reader {
  public:
    Reader(const std::string& source, SettingsLoad& out) : source_(source), out_(out) {}

    void error(const toml::node* at, const std::string& message) {
        error_at(at ? at->source().begin : toml::source_position{1, 1}, message);
    }
    void error_at(const toml::source_position& b, const std::string& message) {
        found_.push_back({b.line, b.column, located(source_, b.line, b.column, message)});
    }
    // Errors in file order, however the checks were ordered; at most kMaxSettingsErrors
    // lines, the last of which then says how many were left out.
    void flush() {
        std::stable_sort(found_.begin(), found_.end(), [](const Found& a, const Found& b) {
            return a.line != b.line ? a.line < b.line : a.column < b.column;
        });
        const std::size_t total = found_.size();
        if (total > kMaxSettingsErrors) {
            found_.resize(kMaxSettingsErrors - 1);
            const std::size_t left_out = total - found_.size();
            found_.push_back(
                {0, 0,
                 source_ + ": error: " + std::to_string(left_out) + " more errors not shown"});
        }
        for (auto& f : found_) out_.errors.push_back(std::move(f.text));
        found_.clear();
    }

    void boolean(const toml::table& t, std::string_view key, bool& dst) {
        const toml::node* n = t.get(key);
        if (!n) return;
        if (const auto v = n->value_exact<bool>()) {
            dst = *v;
        } else {
            error(n,
                  std::string(key) + " must be true or false; keeping " + (dst ? "true" : "false"));
        }
    }

    void unit_float(const toml::table& t, std::string_view key, float& dst) {
        const toml::node* n = t.get(key);
        if (!n) return;
        const auto v = n->is_number() ? n->value<double>() : std::nullopt;
        if (v && std::isfinite(*v) && *v >= 0.0 && *v <= 1.0) {
            dst = static_cast<float>(*v);
        } else {
            std::ostringstream keep;
            keep << dst;
            error(n, std::string(key) + " must be a number from 0 to 1; keeping " + keep.str());
        }
    }

    // A string that must be one of `allowed`; returns the index chosen, or -1.
    int choice(const toml::table& t, std::string_view key, std::span<const std::string> allowed,
               std::string_view current) {
        const toml::node* n = t.get(key);
        if (!n) return -1;
        if (const auto v = n->value_exact<std::string>()) {
            const auto it = std::find(allowed.begin(), allowed.end(), *v);
            if (it != allowed.end()) return static_cast<int>(it - allowed.begin());
        }
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
        error(n, std::string(key) + " must be one of " + list + "; keeping \"" +
                     std::string(current) + "\"");
        return -1;
    }

    // A number from `allowed` (an integer in the file).
    void one_of(const toml::table& t, std::string_view key, std::span<const int> allowed,
                std::optional<int>& dst) {
        const toml::node* n = t.get(key);
        if (!n) return;
        if (const auto v = n->value_exact<std::int64_t>()) {
            if (std::find(allowed.begin(), allowed.end(), *v) != allowed.end()) {
                dst = static_cast<int>(*v);
                return;
            }
        }
        std::string list;
        for (const int a : allowed) list += (list.empty() ? "" : ", ") + std::to_string(a);
        error(n, std::string(key) + " must be one of " + list + "; keeping the level's");
    }

    void ranged_float(const toml::table& t, std::string_view key, float lo, float hi, float& dst) {
        const toml::node* n = t.get(key);
        if (!n) return;
        const auto v = n->is_number() ? n->value<double>() : std::nullopt;
        if (v && std::isfinite(*v) && *v >= lo && *v <= hi) {
            dst = static_cast<float>(*v);
        } else {
            std::ostringstream msg;
            msg << key << " must be a number from " << lo << " to " << hi << "; keeping " << dst;
            error(n, msg.str());
        }
    }

    void max_fps(const toml::table& t, int& dst) {
        const toml::node* n = t.get("max_fps");
        if (!n) return;
        if (const auto v = n->value_exact<std::int64_t>()) {
            if (*v == 0 || (*v >= kMinMaxFps && *v <= kMaxMaxFps)) {
                dst = static_cast<int>(*v);
                return;
            }
        }
        error(n, "max_fps must be 0 (the display's rate without vsync) or " +
                     std::to_string(kMinMaxFps) + " to " + std::to_string(kMaxMaxFps) +
                     "; keeping " + std::to_string(dst));
    }

    void arcade(const toml::table& t, ArcadeDips& dst) {
        const toml::node* n = t.get("arcade");
        if (!n) return;
        const toml::table* a = n->as_table();
        if (!a) {
            error(n, "arcade must be a table such as [arcade] lives = 3; keeping the level's");
            return;
        }
        one_of(*a, "lives", kDipLives, dst.lives);
        one_of(*a, "missile_score", kDipMissileScores, dst.missile_score);
        one_of(*a, "bonus_score", kDipBonusScores, dst.bonus_score);
        for (const auto& [name, value] : *a) {
            const std::string_view k = name.str();
            if (k != "lives" && k != "missile_score" && k != "bonus_score") {
                error_at(name.source().begin, "unknown arcade setting '" + printable(k) +
                                                  "' (lives, missile_score, bonus_score)");
            }
        }
    }

    void keys(const toml::table& t, Bindings& dst) {
        const toml::node* n = t.get("keys");
        if (!n) return;
        const toml::table* keys = n->as_table();
        if (!keys) {
            error(n,
                  "keys must be a table such as [keys] fire = [\"Space\"]; keeping the defaults");
            return;
        }
        for (const auto& [name, value] : *keys) {
            const auto action = action_from_name(name.str());
            if (!action) {
                std::string list;
                for (std::size_t i = 0; i < kActionCount; ++i) {
                    list += (i ? ", " : "") + std::string(action_name(static_cast<Action>(i)));
                }
                error_at(name.source().begin,
                         "unknown action '" + printable(name.str()) + "' (actions: " + list + ")");
                continue;
            }
            std::vector<const toml::node*> items;
            if (const toml::array* arr = value.as_array()) {
                for (const auto& item : *arr) items.push_back(&item);
            } else {
                items.push_back(&value);
            }
            std::vector<KeyBinding> parsed;
            bool ok = true;
            for (const toml::node* item : items) {
                const auto text = item->value_exact<std::string>();
                std::string why;
                const auto key = text ? parse_key(*text, &why) : std::nullopt;
                if (!text) why = "a key must be a string such as \"Space\"";
                if (!key) {
                    error(item, printable(name.str()) + ": " + why + "; keeping the default keys");
                    ok = false;
                    break;
                }
                parsed.push_back(*key);
            }
            if (ok) dst[static_cast<std::size_t>(*action)] = std::move(parsed);
        }
    }

    // [buttons] fire = ["a", "rightshoulder"]: like [keys], one error per bad entry at its
    // position, and the action keeps its default buttons.
    void buttons(const toml::table& t, PadBindings& dst) {
        const toml::node* n = t.get("buttons");
        if (!n) return;
        const toml::table* table = n->as_table();
        if (!table) {
            error(n,
                  "buttons must be a table such as [buttons] fire = [\"a\"]; keeping the "
                  "defaults");
            return;
        }
        for (const auto& [name, value] : *table) {
            const auto action = action_from_name(name.str());
            if (!action) {
                error_at(name.source().begin,
                         "unknown action '" + printable(name.str()) + "' in [buttons]");
                continue;
            }
            std::vector<const toml::node*> items;
            if (const toml::array* arr = value.as_array()) {
                for (const auto& item : *arr) items.push_back(&item);
            } else {
                items.push_back(&value);
            }
            std::vector<int> parsed;
            bool ok = true;
            for (const toml::node* item : items) {
                const auto text = item->value_exact<std::string>();
                std::string why;
                std::optional<int> button;
                if (text)
                    button = parse_button(*text, &why);
                else
                    why = "a button must be a string such as \"a\"";
                if (!button) {
                    error(item,
                          printable(name.str()) + ": " + why + "; keeping the default buttons");
                    ok = false;
                    break;
                }
                parsed.push_back(*button);
            }
            if (ok) dst[static_cast<std::size_t>(*action)] = std::move(parsed);
        }
    }

    void unknown_keys(const toml::table& t) {
        static constexpr std::string_view kKnown[] = {"keys",
                                                      "buttons",
                                                      "volume",
                                                      "mute",
                                                      "vsync",
                                                      "fullscreen",
                                                      "pause_on_focus_loss",
                                                      "preset",
                                                      "style",
                                                      "gamepad",
                                                      "show_fps",
                                                      "difficulty",
                                                      "beam",
                                                      "overlay",
                                                      "hold_41hz",
                                                      "line_method",
                                                      "flashes",
                                                      "colour_safe",
                                                      "ui_scale",
                                                      "max_fps",
                                                      "arcade"};
        for (const auto& [name, value] : t) {
            if (std::find(std::begin(kKnown), std::end(kKnown), name.str()) == std::end(kKnown)) {
                error_at(name.source().begin, "unknown setting '" + printable(name.str()) + "'");
            }
        }
    }

  private:
    struct Found {
        toml::source_index line, column;
        std::string text;
    };
    const std::string& source_;
    SettingsLoad& out_;
    std::vector<Found> found_;
};

std::string quoted(std::string_view s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// `key = value`, or the key commented out with an example when unset.
std::string optional_int(std::string_view key, const std::optional<int>& v, int example,
                         std::string_view comment) {
    std::string line = v ? std::string(key) + " = " + std::to_string(*v)
                         : "# " + std::string(key) + " = " + std::to_string(example);
    return line + "   # " + std::string(comment) + "\n";
}

}  // namespace

std::string_view vsync_name(Vsync v) {
    switch (v) {
        case Vsync::off:
            return "off";
        case Vsync::on:
            return "on";
        case Vsync::adaptive:
            return "adaptive";
    }
    return "on";
}

bool parse_vsync(std::string_view text, Vsync* out) {
    for (const Vsync v : {Vsync::off, Vsync::on, Vsync::adaptive}) {
        if (text == vsync_name(v)) {
            *out = v;
            return true;
        }
    }
    return false;
}

SettingsLoad parse_settings(std::string_view text, const std::string& source,
                            const SettingsChoices& choices) {
    const std::span<const std::string> presets = choices.presets;
    SettingsLoad out;
    out.file_existed = true;
    if (const auto unsafe = unsafe_toml(text, source)) {
        out.errors.push_back(*unsafe + "; using default settings");
        return out;
    }
    toml::table t;
    try {
        t = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        // toml++ counts from 1, but an empty or cut-short file must still say line 1.
        const auto& b = e.source().begin;
        out.errors.push_back(located(source, std::max<std::size_t>(b.line, 1),
                                     std::max<std::size_t>(b.column, 1),
                                     printable(e.description())) +
                             "; using default settings");
        return out;
    }
    Settings& s = out.settings;
    Reader r(source, out);
    r.unit_float(t, "volume", s.volume);
    r.boolean(t, "mute", s.mute);
    r.boolean(t, "fullscreen", s.fullscreen);
    r.boolean(t, "pause_on_focus_loss", s.pause_on_focus_loss);
    r.boolean(t, "show_fps", s.show_fps);

    const std::string vsyncs[] = {"off", "on", "adaptive"};
    if (const int i = r.choice(t, "vsync", vsyncs, vsync_name(s.vsync)); i >= 0) {
        parse_vsync(vsyncs[i], &s.vsync);
    }
    if (const int i = r.choice(t, "preset", presets, s.preset); i >= 0) {
        s.preset = presets[static_cast<std::size_t>(i)];
        out.preset_given = true;
    }
    if (const int i = r.choice(t, "style", choices.styles, s.style); i >= 0) {
        s.style = choices.styles[static_cast<std::size_t>(i)];
        out.style_given = true;
    }
    const std::string beams[] = {"mame", "classic"};
    if (const int i = r.choice(t, "beam", beams, s.beam); i >= 0) {
        s.beam = beams[i];
        out.beam_given = true;
    }
    r.boolean(t, "overlay", s.overlay);
    r.boolean(t, "hold_41hz", s.hold_41hz);
    const std::string line_methods[] = {"compute", "geometry_shader", "auto", "geometry"};
    if (const int i = r.choice(t, "line_method", line_methods, s.line_method); i >= 0) {
        s.line_method = line_methods[i];
    }
    const std::string modes[] = {"tank", "drive"};
    if (const int i = r.choice(t, "gamepad", modes, modes[static_cast<int>(s.gamepad)]); i >= 0) {
        s.gamepad = static_cast<GamepadMode>(i);
    }
    const std::string difficulties[] = {"level", "easy", "normal", "arcade"};
    if (const int i = r.choice(t, "difficulty", difficulties, s.difficulty); i >= 0) {
        s.difficulty = difficulties[i];
    }
    if (const int i = r.choice(t, "flashes", kFlashLevels, s.flashes); i >= 0) {
        s.flashes = kFlashLevels[i];
    }
    r.boolean(t, "colour_safe", s.colour_safe);
    r.ranged_float(t, "ui_scale", kMinUiScale, kMaxUiScale, s.ui_scale);
    r.max_fps(t, s.max_fps);
    r.arcade(t, s.arcade);
    r.keys(t, s.keys);
    r.buttons(t, s.buttons);
    r.unknown_keys(t);
    r.flush();
    return out;
}

SettingsLoad load_settings(const std::filesystem::path& file, const SettingsChoices& choices) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return {};
    std::string text;
    try {
        text = read_file(file, kMaxSettingsBytes);
    } catch (const UserError& e) {
        SettingsLoad out;
        out.file_existed = true;
        out.errors.push_back(std::string(e.what()) + "; using default settings");
        return out;
    }
    return parse_settings(text, printable(file.string()), choices);
}

std::string format_settings(const Settings& s) {
    std::ostringstream o;
    o << "# beamzone settings. Bad values are reported with their line and fall back to the\n"
         "# default; the game rewrites this file only while it has no errors.\n"
      << "volume = " << s.volume << "               # 0.0 .. 1.0\n"
      << "mute = " << (s.mute ? "true" : "false") << "\n"
      << "vsync = " << quoted(vsync_name(s.vsync))
      << "             # \"off\", \"on\" or \"adaptive\"\n"
      << "fullscreen = " << (s.fullscreen ? "true" : "false")
      << "        # borderless desktop fullscreen\n"
      << "pause_on_focus_loss = " << (s.pause_on_focus_loss ? "true" : "false") << "\n"
      << "preset = " << quoted(s.preset)
      << "     # render preset: \"fast\", \"balanced\" or \"high\"\n"
      << "style = " << quoted(s.style)
      << "      # vector, vector-xray (no hidden-line removal), toon, sketch, pop-art, halo or "
         "technical\n"
      << "beam = " << quoted(s.beam)
      << "         # vector beam: \"mame\" (MAME's look, phosphor) or \"classic\"\n"
      << "overlay = " << (s.overlay ? "true" : "false")
      << "         # Battlezone's cabinet overlay: top fifth red, the rest green\n"
      << "hold_41hz = " << (s.hold_41hz ? "true" : "false")
      << "       # the original's ~41 Hz refresh, frames held\n"
      << (s.line_method.empty() ? "# line_method = \"auto\""
                                : "line_method = \"" + s.line_method + "\"")
      << "  # \"auto\" (per frame), \"compute\" or \"geometry_shader\"; unset: the preset's\n"
      << "gamepad = " << quoted(s.gamepad == GamepadMode::tank ? "tank" : "drive")
      << "          # \"tank\" (two sticks, one per tread) or \"drive\" (left stick)\n"
      << "show_fps = " << (s.show_fps ? "true" : "false")
      << "         # frame rate and frame-time readout\n"
      << "difficulty = " << quoted(s.difficulty)
      << "      # \"easy\", \"normal\", \"arcade\", or \"level\" (each level's own)\n"
      << "flashes = " << quoted(s.flashes)
      << "         # \"full\", \"soft\" or \"off\": beam flicker, hit flashes, phosphor trails\n"
      << "colour_safe = " << (s.colour_safe ? "true" : "false")
      << "     # red drawn violet-blue, for red-green colour blindness\n"
      << "ui_scale = " << s.ui_scale << "          # menu and HUD text, 1.0 .. 2.0\n"
      << "max_fps = " << s.max_fps
      << "           # 0: the display's refresh rate when vsync is off; else a cap, 20 .. 1000\n"
      << "\n# The arcade machine's DIP switches; a missing key keeps the level's rule.\n"
      << "[arcade]\n"
      << optional_int("lives", s.arcade.lives, 3, "tanks at the start: 2, 3, 4 or 5")
      << optional_int("missile_score", s.arcade.missile_score, 10000,
                      "missiles from: 5000, 10000, 20000 or 30000")
      << optional_int("bonus_score", s.arcade.bonus_score, 15000,
                      "first bonus tank (second at 100000): 0 (none), 15000, 20000, 50000")
      << "\n# Keys per action, as SDL scancode names (\"Q\", \"Space\", \"Left Ctrl\", "
         "\"Alt+Return\").\n"
      << "[keys]\n";
    for (std::size_t i = 0; i < kActionCount; ++i) {
        o << action_name(static_cast<Action>(i)) << " = [";
        for (std::size_t k = 0; k < s.keys[i].size(); ++k) {
            o << (k ? ", " : "") << quoted(key_name(s.keys[i][k]));
        }
        o << "]\n";
    }
    o << "\n# Gamepad buttons per action, as SDL names them (\"a\", \"b\", \"x\", \"y\", "
         "\"start\",\n# \"leftshoulder\", \"rightshoulder\", \"dpup\"). The menus always "
         "take the d-pad, A, B and Start.\n"
      << "[buttons]\n";
    for (std::size_t i = 0; i < kActionCount; ++i) {
        o << action_name(static_cast<Action>(i)) << " = [";
        for (std::size_t k = 0; k < s.buttons[i].size(); ++k) {
            o << (k ? ", " : "") << quoted(button_name(s.buttons[i][k]));
        }
        o << "]\n";
    }
    return o.str();
}

void save_settings(const std::filesystem::path& file, const Settings& s) {
    write_file_atomic(file, format_settings(s));
}

}  // namespace bz::platform
