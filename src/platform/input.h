#pragma once
// Turns SDL keyboard and game-controller events into one platform-independent InputState per
// simulation tick, the one-shot actions (pause, screenshot, ...) pressed since the last frame,
// and menu keys. Works only from events, so tests can feed it synthetic ones without a window.
//
// Presses are latched as events: a key pressed and released between two ticks (a quick tap at
// a low frame rate) still reaches the next tick's state once. Held state drives the treads.
#include <array>
#include <map>
#include <optional>
#include <vector>

#include "platform/bindings.h"
#include "platform/pad_bindings.h"

union SDL_Event;

namespace bz::platform {

enum class GamepadMode {
    tank,   // left stick Y = left tread, right stick Y = right tread
    drive,  // left stick: Y = forward/back, X = turn
};

struct InputState {
    float left_tread = 0.0f;  // -1 (full back) .. +1 (full forward)
    float right_tread = 0.0f;
    bool fire = false;
    // Menu directions (held): the drive keys and a pad's d-pad.
    bool up = false, down = false, left = false, right = false;
};

// What one key or button press means to a menu. Each press gives at most one; which keys give
// which follows the bindings (the drive keys move, start and fire confirm, back and pause go
// back), so a rebound key works in the menus too.
enum class MenuKey : std::uint8_t { up, down, left, right, confirm, back };

// Stick values in -1..1 with SDL's sign (y grows downward), triggers 0..1.
struct PadAxes {
    float left_x = 0.0f, left_y = 0.0f, right_x = 0.0f, right_y = 0.0f;
    float trigger_left = 0.0f, trigger_right = 0.0f;
};
// Tread commands of one pad, after a radial dead zone on each stick.
InputState pad_to_treads(const PadAxes& axes, GamepadMode mode);

class Input {
  public:
    explicit Input(Bindings bindings = default_bindings(), GamepadMode mode = GamepadMode::tank,
                   PadBindings buttons = default_pad_bindings());

    // Feeds one event; one-shot actions it triggers are queued for take_pressed().
    void handle_event(const SDL_Event& event);
    // Keyboard and all connected pads together, clamped to -1..1: what is held right now.
    InputState state() const;
    // The state for the next simulation tick: what is held, plus each button (fire and the
    // menu directions) pressed since the previous tick even if it was released already. A
    // press and release within one tick counts once; a release and new press of a held button
    // within one tick gives one tick up first, so the game sees the second press too.
    InputState next_tick();
    std::vector<Action> take_pressed();
    std::vector<MenuKey> take_menu_keys();

    // Key rebinding: while capturing, the next key press is kept for take_captured() instead of
    // acting (Escape cancels: take_captured() then gives kCaptureCancelled). A modifier key is
    // taken on release when no other key came with it, so both "Left Ctrl" and "Alt+Return" can
    // be bound.
    void begin_capture();
    void cancel_capture() { capturing_ = false; }
    bool capturing() const { return capturing_; }
    std::optional<KeyBinding> take_captured();
    // A gamepad button pressed while capturing is kept here instead (take_captured() then gives
    // nothing): the keys page binds it to the action as a button.
    std::optional<int> take_captured_button();
    static constexpr KeyBinding kCaptureCancelled{-1, kModNone};

    bool key_held(int scancode) const;  // raw keys, for the --edit free-fly camera
    void set_bindings(Bindings b) { bindings_ = std::move(b); }
    void set_pad_bindings(PadBindings b) { buttons_ = std::move(b); }
    void set_gamepad_mode(GamepadMode m) { mode_ = m; }
    // Forgets held keys and buttons, e.g. when the window loses focus (no stuck keys).
    void release_all();

  private:
    struct Pad {
        PadAxes axes;
        std::array<bool, 32> buttons{};
    };
    // Buttons whose presses are latched between ticks.
    enum Latched : std::uint8_t {
        latch_fire,
        latch_up,
        latch_down,
        latch_left,
        latch_right,
        latched_count
    };
    struct Latch {
        bool pending = false;  // pressed since the last tick
        bool sent = false;     // what the last tick got
    };
    bool action_held(Action a) const;
    void key_down(int scancode, unsigned sdl_mod, bool repeat);
    void key_up(int scancode, unsigned sdl_mod);
    void capture_key_down(int scancode, unsigned sdl_mod);
    void pad_button(const SDL_Event& e);
    void pad_axis(const SDL_Event& e);
    void latch_action(Action a);
    void menu(MenuKey k) { menu_keys_.push_back(k); }

    Bindings bindings_;
    GamepadMode mode_;
    PadBindings buttons_;
    std::array<bool, 512> keys_{};  // SDL_NUM_SCANCODES
    std::uint8_t mods_ = kModNone;
    std::map<int, Pad> pads_;  // by SDL joystick instance id
    std::vector<Action> pressed_;
    std::vector<MenuKey> menu_keys_;
    std::array<Latch, latched_count> latches_{};
    bool capturing_ = false;
    int capture_modifier_ = -1;  // a modifier key down while capturing, or -1
    std::optional<KeyBinding> captured_;
    std::optional<int> captured_button_;
};

}  // namespace bz::platform
