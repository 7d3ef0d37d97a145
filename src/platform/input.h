#pragma once
// Turns SDL keyboard and game-controller events into one platform-independent InputState per
// frame plus the one-shot actions (pause, screenshot, ...) pressed since the last frame.
// Works only from events, so tests can feed it synthetic ones without a window.
#include <array>
#include <map>
#include <vector>

#include "platform/bindings.h"

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

// Stick values in -1..1 with SDL's sign (y grows downward), triggers 0..1.
struct PadAxes {
    float left_x = 0.0f, left_y = 0.0f, right_x = 0.0f, right_y = 0.0f;
    float trigger_left = 0.0f, trigger_right = 0.0f;
};
// Tread commands of one pad, after a radial dead zone on each stick.
InputState pad_to_treads(const PadAxes& axes, GamepadMode mode);

class Input {
  public:
    explicit Input(Bindings bindings = default_bindings(), GamepadMode mode = GamepadMode::tank);

    // Feeds one event; one-shot actions it triggers are queued for take_pressed().
    void handle_event(const SDL_Event& event);
    // Keyboard and all connected pads together, clamped to -1..1.
    InputState state() const;
    std::vector<Action> take_pressed();

    bool key_held(int scancode) const;  // raw keys, for the --edit free-fly camera
    void set_bindings(Bindings b) { bindings_ = std::move(b); }
    void set_gamepad_mode(GamepadMode m) { mode_ = m; }
    // Forgets held keys and buttons, e.g. when the window loses focus (no stuck keys).
    void release_all();

  private:
    struct Pad {
        PadAxes axes;
        std::array<bool, 32> buttons{};
    };
    bool action_held(Action a) const;
    void key_down(int scancode, unsigned sdl_mod, bool repeat);

    Bindings bindings_;
    GamepadMode mode_;
    std::array<bool, 512> keys_{};  // SDL_NUM_SCANCODES
    std::uint8_t mods_ = kModNone;
    std::map<int, Pad> pads_;  // by SDL joystick instance id
    std::vector<Action> pressed_;
};

}  // namespace bz::platform
