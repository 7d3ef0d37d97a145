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

TEST(InputLatch, TapBetweenTwoTicksReachesTheNextTickOnce) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_SPACE));
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_SPACE));
    EXPECT_FALSE(in.state().fire);  // nothing held: the old per-frame read lost this tap
    EXPECT_TRUE(in.next_tick().fire);
    EXPECT_FALSE(in.next_tick().fire);
    EXPECT_FALSE(in.next_tick().fire);
}

TEST(InputLatch, SeveralTapsWithinOneTickCountOnce) {
    Input in;
    for (int i = 0; i < 3; ++i) {
        in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_UP));
        in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_UP));
    }
    EXPECT_TRUE(in.next_tick().up);
    EXPECT_FALSE(in.next_tick().up);
}

TEST(InputLatch, HeldButtonStaysDownWithoutExtraPresses) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_SPACE));
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(in.next_tick().fire) << i;
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_SPACE));
    EXPECT_FALSE(in.next_tick().fire);
}

TEST(InputLatch, ReleaseAndPressWithinOneTickGivesASecondPress) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_SPACE));
    EXPECT_TRUE(in.next_tick().fire);
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_SPACE));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_SPACE));
    EXPECT_FALSE(in.next_tick().fire);  // the release the game must see
    EXPECT_TRUE(in.next_tick().fire);   // the second press
    EXPECT_TRUE(in.next_tick().fire);   // still held
}

TEST(InputLatch, HeldKeysStillDriveTheTreads) {
    Input in;
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_Q));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_E));
    const InputState s = in.next_tick();
    EXPECT_EQ(s.left_tread, 1.0f);
    EXPECT_EQ(s.right_tread, 1.0f);
    EXPECT_EQ(in.next_tick().left_tread, 1.0f);
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_Q));
    EXPECT_EQ(in.next_tick().left_tread, 0.0f);
}

TEST(InputLatch, PadButtonAndTriggerPressesAreLatched) {
    Input in;
    SDL_Event b{};
    b.type = SDL_CONTROLLERBUTTONDOWN;
    b.cbutton.which = 3;
    b.cbutton.button = SDL_CONTROLLER_BUTTON_A;
    in.handle_event(b);
    b.type = SDL_CONTROLLERBUTTONUP;
    in.handle_event(b);
    EXPECT_TRUE(in.next_tick().fire);
    EXPECT_FALSE(in.next_tick().fire);
    SDL_Event t{};
    t.type = SDL_CONTROLLERAXISMOTION;
    t.caxis.which = 3;
    t.caxis.axis = SDL_CONTROLLER_AXIS_TRIGGERRIGHT;
    t.caxis.value = 32000;
    in.handle_event(t);
    t.caxis.value = 0;
    in.handle_event(t);
    EXPECT_TRUE(in.next_tick().fire);
    EXPECT_FALSE(in.next_tick().fire);
}

// Taps of `tap_ms` every `period_s` seconds for `seconds`, delivered frame by frame at `fps`
// (each frame's events, then that frame's 60 Hz ticks); returns the presses the ticks saw.
struct TapRun {
    int taps = 0;
    int seen_latched = 0;  // rising edges of next_tick().fire
    int seen_sampled = 0;  // rising edges of state() read once per frame (the old way)
};

TapRun run_taps(double fps, double tap_ms, double period_s, double seconds) {
    constexpr double kTick = 1.0 / 60.0;
    struct Timed {
        double t;
        bool down;
    };
    std::vector<Timed> events;
    TapRun r;
    // Start off the frame grid (0.0123 s) so taps land at every phase within a frame.
    for (double t = 0.0123; t + tap_ms / 1000.0 < seconds; t += period_s) {
        events.push_back({t, true});
        events.push_back({t + tap_ms / 1000.0, false});
        ++r.taps;
    }
    Input in;
    std::size_t next = 0;
    double accumulator = 0.0;
    bool last_latched = false, last_sampled = false;
    const double frame = 1.0 / fps;
    for (double now = frame; now <= seconds + frame; now += frame) {
        while (next < events.size() && events[next].t <= now) {
            in.handle_event(key(events[next].down ? SDL_KEYDOWN : SDL_KEYUP, SDL_SCANCODE_SPACE));
            ++next;
        }
        accumulator += frame;
        const bool sampled = in.state().fire;
        while (accumulator >= kTick - 1e-9) {
            accumulator -= kTick;
            const bool latched = in.next_tick().fire;
            if (latched && !last_latched) ++r.seen_latched;
            last_latched = latched;
            if (sampled && !last_sampled) ++r.seen_sampled;
            last_sampled = sampled;
        }
    }
    return r;
}

TEST(InputLatch, EveryQuickTapCountsOnceAt10_30And60Fps) {
    for (const double fps : {10.0, 30.0, 60.0}) {
        for (const double tap_ms : {5.0, 30.0, 80.0}) {
            const TapRun r = run_taps(fps, tap_ms, 0.37, 12.0);
            EXPECT_GT(r.taps, 30);
            EXPECT_EQ(r.seen_latched, r.taps) << fps << " fps, " << tap_ms << " ms taps";
        }
    }
    // The run really exercises the problem: reading "held now" once a frame loses short taps
    // at a low frame rate.
    const TapRun slow = run_taps(10.0, 30.0, 0.37, 12.0);
    EXPECT_LT(slow.seen_sampled, slow.taps / 2);
}

TEST(InputLatch, LongHoldsStillCountOnceEach) {
    for (const double fps : {10.0, 30.0, 60.0}) {
        const TapRun r = run_taps(fps, 250.0, 0.6, 12.0);
        EXPECT_EQ(r.seen_latched, r.taps) << fps << " fps";
    }
}

TEST(InputMenu, KeysFollowTheBindingsOneMenuKeyPerPress) {
    Input in;
    auto press = [&in](SDL_Scancode sc, Uint16 mod = KMOD_NONE) {
        in.handle_event(key(SDL_KEYDOWN, sc, mod));
        in.handle_event(key(SDL_KEYUP, sc));
    };
    press(SDL_SCANCODE_DOWN);
    press(SDL_SCANCODE_W);
    press(SDL_SCANCODE_RETURN);
    press(SDL_SCANCODE_SPACE);
    press(SDL_SCANCODE_ESCAPE);
    press(SDL_SCANCODE_BACKSPACE);
    press(SDL_SCANCODE_RETURN, KMOD_LALT);  // fullscreen, not confirm
    press(SDL_SCANCODE_F12);                // no menu meaning
    const std::vector<MenuKey> want = {MenuKey::down,    MenuKey::up,   MenuKey::confirm,
                                       MenuKey::confirm, MenuKey::back, MenuKey::back};
    EXPECT_EQ(in.take_menu_keys(), want);
    EXPECT_TRUE(in.take_menu_keys().empty());
    // Held arrows repeat in menus; held Return does not confirm twice.
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_DOWN, KMOD_NONE, true));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RETURN, KMOD_NONE, true));
    EXPECT_EQ(in.take_menu_keys(), std::vector<MenuKey>{MenuKey::down});
}

TEST(InputMenu, RebindingMovesTheMenuKeysToo) {
    Bindings b = default_bindings();
    b[static_cast<std::size_t>(Action::drive_back)] = {parse_key("J", nullptr).value()};
    Input in(b);
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_J));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_DOWN));  // no longer bound
    EXPECT_EQ(in.take_menu_keys(), std::vector<MenuKey>{MenuKey::down});
}

TEST(InputMenu, GamepadDrivesMenus) {
    Input in;
    auto pad = [&in](SDL_GameControllerButton btn) {
        SDL_Event e{};
        e.type = SDL_CONTROLLERBUTTONDOWN;
        e.cbutton.which = 1;
        e.cbutton.button = static_cast<Uint8>(btn);
        in.handle_event(e);
        e.type = SDL_CONTROLLERBUTTONUP;
        in.handle_event(e);
    };
    pad(SDL_CONTROLLER_BUTTON_DPAD_DOWN);
    pad(SDL_CONTROLLER_BUTTON_A);
    pad(SDL_CONTROLLER_BUTTON_B);
    pad(SDL_CONTROLLER_BUTTON_START);
    SDL_Event stick{};
    stick.type = SDL_CONTROLLERAXISMOTION;
    stick.caxis.which = 1;
    stick.caxis.axis = SDL_CONTROLLER_AXIS_LEFTY;
    stick.caxis.value = -30000;  // pushed up
    in.handle_event(stick);
    stick.caxis.value = -31000;  // still up: no second press
    in.handle_event(stick);
    const std::vector<MenuKey> want = {MenuKey::down, MenuKey::confirm, MenuKey::back,
                                       MenuKey::confirm, MenuKey::up};
    EXPECT_EQ(in.take_menu_keys(), want);
}

TEST(InputCapture, NextKeyIsCapturedNotActedOn) {
    Input in;
    in.begin_capture();
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_K));
    EXPECT_TRUE(in.take_pressed().empty());
    EXPECT_TRUE(in.take_menu_keys().empty());
    EXPECT_EQ(in.take_captured(), (KeyBinding{SDL_SCANCODE_K, kModNone}));
    EXPECT_FALSE(in.capturing());
    EXPECT_FALSE(in.take_captured());
}

TEST(InputCapture, ModifiersCombineOrStandAlone) {
    Input in;
    in.begin_capture();
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_LALT, KMOD_LALT));
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RETURN, KMOD_LALT));
    EXPECT_EQ(in.take_captured(), (KeyBinding{SDL_SCANCODE_RETURN, kModAlt}));
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_RETURN, KMOD_LALT));
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_LALT));
    in.begin_capture();
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_RCTRL, KMOD_RCTRL));
    EXPECT_FALSE(in.take_captured());  // might still become Ctrl+something
    in.handle_event(key(SDL_KEYUP, SDL_SCANCODE_RCTRL));
    EXPECT_EQ(in.take_captured(), (KeyBinding{SDL_SCANCODE_RCTRL, kModNone}));
    in.begin_capture();
    in.handle_event(key(SDL_KEYDOWN, SDL_SCANCODE_ESCAPE));
    EXPECT_EQ(in.take_captured(), Input::kCaptureCancelled);
}

}  // namespace
}  // namespace bz::platform
