#pragma once
// Player actions and the keys bound to them. Keys are named as SDL names scancodes ("Q",
// "Space", "Left Ctrl", "Keypad +"), optionally with modifiers ("Alt+Return"), so a layout
// change moves the physical key, not its label, and the settings file stays human readable.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bz::platform {

enum class Action : std::uint8_t {
    // Held: sampled every tick.
    left_tread_forward,
    left_tread_back,
    right_tread_forward,
    right_tread_back,
    drive_forward,
    drive_back,
    turn_left,
    turn_right,
    fire,
    // Pressed: one event per key press.
    pause,
    fullscreen,
    screenshot,
    reload_shaders,
    mute,
    volume_up,
    volume_down,
    quit,
    show_fps,           // the frame-rate and frame-time readout
    start,              // begin a game, confirm (menus, initials)
    back,               // menus and initials: go back, delete
    cycle_style,        // the next look (scene::next_style), for this run only
    vector_screenshot,  // the frame's exact visible lines as SVG, beside the screenshots
    count
};
constexpr std::size_t kActionCount = static_cast<std::size_t>(Action::count);

constexpr bool is_held_action(Action a) {
    return a <= Action::fire;
}
std::string_view action_name(Action a);  // "left_tread_forward", as in the settings file
std::optional<Action> action_from_name(std::string_view name);

enum Modifier : std::uint8_t { kModNone = 0, kModAlt = 1, kModCtrl = 2, kModShift = 4 };

struct KeyBinding {
    int scancode = 0;  // SDL_Scancode
    std::uint8_t mods = kModNone;
    bool operator==(const KeyBinding&) const = default;
};

// "Q", "Space", "Alt+Return", "Ctrl+Shift+F5" (modifier names are case-insensitive). Returns
// nullopt with the reason in *error for an unknown key name.
std::optional<KeyBinding> parse_key(std::string_view text, std::string* error);
std::string key_name(const KeyBinding& key);  // parse_key(key_name(k)) == k

using Bindings = std::array<std::vector<KeyBinding>, kActionCount>;
Bindings default_bindings();

// The other action bound to exactly `key`, if any: the options screen shows it as a conflict.
std::optional<Action> conflicting_action(const Bindings& b, Action a, const KeyBinding& key);
// Every action with a key that another action also has.
std::vector<Action> actions_in_conflict(const Bindings& b);
// The keys of an action for on-screen hints, in capitals: "P / ESCAPE", or "-" for none.
// At most `max_keys` keys are named.
std::string keys_label(const Bindings& b, Action a, std::size_t max_keys = 2);

// Maps SDL's modifier state (KMOD_*) to Modifier bits, left and right alike.
std::uint8_t modifiers_from_sdl(unsigned sdl_mod);

}  // namespace bz::platform
