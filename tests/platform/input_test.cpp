#include "platform/input.h"

#include <SDL_events.h>
#include <gtest/gtest.h>

namespace bz::platform {
namespace {

SDL_Event key(Uint32 type, SDL_Scancode sc, Uint16 mod = KMOD_NONE, bool repeat = false) {
    SDL_Event e{};
    e.type = type;
    e.key.keysym.scancode = sc;
    e.key.keysym.mod = mod;
    e.key.repeat = repeat ? 1 : 0;
    return e;
}

SDL_Event axis(SDL_JoystickID pad, SDL_GameControllerAxis a, Sint16 value) {
    SDL_Event e{};
    e.type = SDL_CONTROLLERAXISMOTION;
    e.caxis.which = pad;
    e.caxis.axis = static_cast<Uint8>(a);
    e.caxis.value = value;
    return e;
}

SDL_Event button(SDL_JoystickID pad, SDL_GameControllerButton b, bool down) {
    SDL_Event e{};
    e.type = down ? SDL_CONTROLLERBUTTONDOWN : SDL_CONTROLLERBUTTONUP;
    e.cbutton.which = pad;
    e.cbutton.button = static_cast<Uint8>(b);
    return e;
}

TEST(Input, TankKeysDriveEachTread) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_Q));
    EXPECT_EQ(in.state().left_tread, 1.0f);
    EXPECT_EQ(in.state().right_tread, 0.0f);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_D));
    EXPECT_EQ(in.state().right_tread, -1.0f);
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_Q));
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_D));
    EXPECT_EQ(in.state().left_tread, 0.0f);
    EXPECT_EQ(in.state().right_tread, 0.0f);
}

TEST(Input, DriveKeysMixIntoTreadsAndClamp) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_UP));
    EXPECT_EQ(in.state().left_tread, 1.0f);
    EXPECT_EQ(in.state().right_tread, 1.0f);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RIGHT));  // forward + right: pivot on right tread
    EXPECT_EQ(in.state().left_tread, 1.0f);                 // 2 clamped to 1
    EXPECT_EQ(in.state().right_tread, 0.0f);
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_UP));
    EXPECT_EQ(in.state().left_tread, 1.0f);  // turning in place
    EXPECT_EQ(in.state().right_tread, -1.0f);
}

TEST(Input, FireIsHeldAndPausePressedOnce) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_LCTRL, KMOD_LCTRL));
    EXPECT_TRUE(in.state().fire);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_P, KMOD_LCTRL));        // extra modifiers allowed
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_P, KMOD_LCTRL, true));  // auto-repeat: ignored
    EXPECT_EQ(in.take_pressed(), std::vector<Action>{Action::pause});
    EXPECT_TRUE(in.take_pressed().empty());
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_LCTRL));
    EXPECT_FALSE(in.state().fire);
}

TEST(Input, MostSpecificBindingWins) {
    Bindings b = default_bindings();
    b[static_cast<std::size_t>(Action::screenshot)] = {parse_key("Return", nullptr).value()};
    Input in(b);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RETURN, KMOD_LALT));
    EXPECT_EQ(in.take_pressed(), std::vector<Action>{Action::fullscreen});
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_RETURN));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RETURN));
    // Equally specific bindings all fire (Return is also start by default).
    EXPECT_EQ(in.take_pressed(), (std::vector<Action>{Action::screenshot, Action::start}));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_F11));
    EXPECT_EQ(in.take_pressed(), std::vector<Action>{Action::fullscreen});
}

TEST(Input, MenuKeys) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_UP));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_LEFT));
    EXPECT_TRUE(in.state().up);
    EXPECT_TRUE(in.state().left);
    EXPECT_FALSE(in.state().down);
    EXPECT_FALSE(in.state().right);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RETURN));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_BACKSPACE));
    EXPECT_EQ(in.take_pressed(), (std::vector<Action>{Action::start, Action::back}));
}

TEST(Input, RemappedKeys) {
    Bindings b = default_bindings();
    b[static_cast<std::size_t>(Action::fire)] = {parse_key("F", nullptr).value()};
    Input in(b);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_SPACE));
    EXPECT_FALSE(in.state().fire);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_F));
    EXPECT_TRUE(in.state().fire);
}

TEST(Input, FocusLossReleasesKeys) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_W));
    EXPECT_TRUE(in.key_held(SDL_SCANCODE_W));
    SDL_Event e{};
    e.type = SDL_WINDOWEVENT;
    e.window.event = SDL_WINDOWEVENT_FOCUS_LOST;
    in.handle_event(e);
    EXPECT_FALSE(in.key_held(SDL_SCANCODE_W));
    EXPECT_EQ(in.state().left_tread, 0.0f);
}

TEST(Input, OutOfRangeScancodesAreIgnored) {
    Input in;
    // Inside the enum's value range (so no UB) but past SDL_NUM_SCANCODES.
    in.handle_event(key(SDL_KEYDOWN, static_cast<SDL_Scancode>(1000)));
    in.handle_event(key(SDL_KEYUP, static_cast<SDL_Scancode>(1001)));
    EXPECT_FALSE(in.key_held(1000));
    EXPECT_FALSE(in.key_held(-5));
    EXPECT_TRUE(in.take_pressed().empty());
}

TEST(Input, GamepadTankSticksAndFire) {
    Input in;
    in.handle_event(axis(3, SDL_CONTROLLER_AXIS_LEFTY, -32768));  // stick pushed away
    in.handle_event(axis(3, SDL_CONTROLLER_AXIS_RIGHTY, 32767));
    EXPECT_FLOAT_EQ(in.state().left_tread, 1.0f);
    EXPECT_FLOAT_EQ(in.state().right_tread, -1.0f);
    EXPECT_FALSE(in.state().fire);
    in.handle_event(axis(3, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 30000));
    EXPECT_TRUE(in.state().fire);
    in.handle_event(axis(3, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 0));
    in.handle_event(button(3, SDL_CONTROLLER_BUTTON_A, true));
    EXPECT_TRUE(in.state().fire);
    in.handle_event(button(3, SDL_CONTROLLER_BUTTON_START, true));
    EXPECT_EQ(in.take_pressed(), (std::vector<Action>{Action::pause, Action::start}));
    in.handle_event(button(3, SDL_CONTROLLER_BUTTON_B, true));
    EXPECT_EQ(in.take_pressed(), std::vector<Action>{Action::back});
    in.handle_event(button(3, SDL_CONTROLLER_BUTTON_DPAD_DOWN, true));
    EXPECT_TRUE(in.state().down);
    EXPECT_FALSE(in.state().up);

    // Unplugging forgets the pad: no tread stuck at full.
    SDL_Event removed{};
    removed.type = SDL_CONTROLLERDEVICEREMOVED;
    removed.cdevice.which = 3;
    in.handle_event(removed);
    EXPECT_EQ(in.state().left_tread, 0.0f);
    EXPECT_FALSE(in.state().fire);
}

TEST(Input, PadDeadZoneAndDriveMode) {
    PadAxes a;
    a.left_y = -0.15f;  // resting drift
    a.right_x = 0.1f;
    InputState s = pad_to_treads(a, GamepadMode::tank);
    EXPECT_EQ(s.left_tread, 0.0f);
    EXPECT_EQ(s.right_tread, 0.0f);

    a = {};
    a.left_y = -0.6f;  // halfway past the dead zone
    s = pad_to_treads(a, GamepadMode::tank);
    EXPECT_NEAR(s.left_tread, 0.5f, 1e-5f);

    a = {};
    a.left_y = -1.0f;
    s = pad_to_treads(a, GamepadMode::drive);
    EXPECT_FLOAT_EQ(s.left_tread, 1.0f);
    EXPECT_FLOAT_EQ(s.right_tread, 1.0f);
    a = {};
    a.left_x = 1.0f;  // stick right: spin clockwise
    s = pad_to_treads(a, GamepadMode::drive);
    EXPECT_FLOAT_EQ(s.left_tread, 1.0f);
    EXPECT_FLOAT_EQ(s.right_tread, -1.0f);
}

}  // namespace
}  // namespace bz::platform
