#include "platform/bindings.h"

#include <SDL_keyboard.h>

#include <algorithm>
#include <cctype>
#include <utility>

#include "core/text/ascii_case.h"
#include "core/text/printable.h"

namespace bz::platform {

namespace {

constexpr std::array<std::string_view, kActionCount> kNames = {
    "left_tread_forward",
    "left_tread_back",
    "right_tread_forward",
    "right_tread_back",
    "drive_forward",
    "drive_back",
    "turn_left",
    "turn_right",
    "fire",
    "pause",
    "fullscreen",
    "screenshot",
    "reload_shaders",
    "mute",
    "volume_up",
    "volume_down",
    "quit",
    "show_fps",
    "start",
    "back",
    "cycle_style",
    "vector_screenshot",
};

struct ModifierName {
    std::string_view name;
    std::uint8_t bit;
};
constexpr ModifierName kModifiers[] = {{"alt", kModAlt}, {"ctrl", kModCtrl}, {"shift", kModShift}};

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i]))) {
            return false;
        }
    }
    return true;
}

KeyBinding key(const char* name, std::uint8_t mods = kModNone) {
    return {static_cast<int>(SDL_GetScancodeFromName(name)), mods};
}

}  // namespace

std::string_view action_name(Action a) {
    return kNames.at(static_cast<std::size_t>(a));
}

std::optional<Action> action_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kActionCount; ++i) {
        if (kNames[i] == name) return static_cast<Action>(i);
    }
    return std::nullopt;
}

std::optional<KeyBinding> parse_key(std::string_view text, std::string* error) {
    KeyBinding k;
    std::string_view rest = text;
    // Peel "Mod+" prefixes; the key itself may contain '+' ("Keypad +"), so only known
    // modifier names count as prefixes.
    for (bool peeled = true; peeled;) {
        peeled = false;
        const std::size_t plus = rest.find('+');
        if (plus == std::string_view::npos || plus + 1 >= rest.size()) break;
        for (const auto& m : kModifiers) {
            if (iequals(rest.substr(0, plus), m.name)) {
                k.mods |= m.bit;
                rest.remove_prefix(plus + 1);
                peeled = true;
                break;
            }
        }
    }
    const std::string name(rest);
    const SDL_Scancode sc =
        name.empty() ? SDL_SCANCODE_UNKNOWN : SDL_GetScancodeFromName(name.c_str());
    if (sc == SDL_SCANCODE_UNKNOWN) {
        if (error) {
            *error = "unknown key '" + printable(text) +
                     "' (use SDL scancode names such as \"Q\", \"Space\", \"Left Ctrl\", "
                     "\"Alt+Return\")";
        }
        return std::nullopt;
    }
    k.scancode = static_cast<int>(sc);
    return k;
}

std::string key_name(const KeyBinding& k) {
    std::string out;
    if (k.mods & kModAlt) out += "Alt+";
    if (k.mods & kModCtrl) out += "Ctrl+";
    if (k.mods & kModShift) out += "Shift+";
    out += SDL_GetScancodeName(static_cast<SDL_Scancode>(k.scancode));
    return out;
}

Bindings default_bindings() {
    Bindings b;
    auto set = [&b](Action a, std::vector<KeyBinding> keys) {
        b[static_cast<std::size_t>(a)] = std::move(keys);
    };
    // Two-stick tank controls on the keyboard, as on the 1980 cabinet.
    set(Action::left_tread_forward, {key("Q")});
    set(Action::left_tread_back, {key("A")});
    set(Action::right_tread_forward, {key("E")});
    set(Action::right_tread_back, {key("D")});
    // Car-style driving; W+A and W+D then steer because A and D pull one tread back.
    set(Action::drive_forward, {key("Up"), key("W")});
    set(Action::drive_back, {key("Down"), key("S")});
    set(Action::turn_left, {key("Left")});
    set(Action::turn_right, {key("Right")});
    set(Action::fire, {key("Space"), key("Left Ctrl"), key("Right Ctrl")});
    set(Action::pause, {key("P"), key("Escape")});
    set(Action::fullscreen, {key("F11"), key("Return", kModAlt)});
    set(Action::screenshot, {key("F12")});
    set(Action::reload_shaders, {key("F5")});
    set(Action::mute, {key("M")});
    set(Action::volume_up, {key("="), key("Keypad +")});
    set(Action::volume_down, {key("-"), key("Keypad -")});
    set(Action::quit, {key("F10"), key("F4", kModAlt)});
    set(Action::show_fps, {key("F3")});
    set(Action::start, {key("Return"), key("Keypad Enter"), key("1")});
    set(Action::back, {key("Backspace")});
    set(Action::cycle_style, {key("F6")});
    set(Action::vector_screenshot, {key("F12", kModShift)});
    return b;
}

std::optional<Action> conflicting_action(const Bindings& b, Action a, const KeyBinding& key) {
    for (std::size_t i = 0; i < kActionCount; ++i) {
        if (static_cast<Action>(i) == a) continue;
        if (std::find(b[i].begin(), b[i].end(), key) != b[i].end()) return static_cast<Action>(i);
    }
    return std::nullopt;
}

std::vector<Action> actions_in_conflict(const Bindings& b) {
    std::vector<Action> out;
    for (std::size_t i = 0; i < kActionCount; ++i) {
        const auto a = static_cast<Action>(i);
        for (const KeyBinding& k : b[i]) {
            if (conflicting_action(b, a, k)) {
                out.push_back(a);
                break;
            }
        }
    }
    return out;
}

std::string keys_label(const Bindings& b, Action a, std::size_t max_keys) {
    const auto& keys = b[static_cast<std::size_t>(a)];
    std::string out;
    for (std::size_t i = 0; i < keys.size() && i < max_keys; ++i) {
        if (i) out += " / ";
        out += key_name(keys[i]);
    }
    out = ascii_upper(std::move(out));
    return out.empty() ? "-" : out;
}

std::uint8_t modifiers_from_sdl(unsigned sdl_mod) {
    std::uint8_t m = kModNone;
    if (sdl_mod & KMOD_ALT) m |= kModAlt;
    if (sdl_mod & KMOD_CTRL) m |= kModCtrl;
    if (sdl_mod & KMOD_SHIFT) m |= kModShift;
    return m;
}

}  // namespace bz::platform
