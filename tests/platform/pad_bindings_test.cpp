// Gamepad button rebinding: names as SDL gives them, the [buttons] section of the settings
// file with file:line:col errors, and the pad's button events reaching the bound actions
// through the game-controller event path (headless: no pad, no SDL_Init).
#include "platform/pad_bindings.h"

#include <SDL_events.h>
#include <SDL_gamecontroller.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "platform/input.h"
#include "platform/settings.h"

namespace bz::platform {
namespace {

SDL_Event pad_button(SDL_GameControllerButton b, bool down, SDL_JoystickID pad = 2) {
    SDL_Event e{};
    e.type = down ? SDL_CONTROLLERBUTTONDOWN : SDL_CONTROLLERBUTTONUP;
    e.cbutton.which = pad;
    e.cbutton.button = static_cast<Uint8>(b);
    return e;
}

bool has(const std::vector<Action>& v, Action a) {
    return std::find(v.begin(), v.end(), a) != v.end();
}

TEST(PadBindings, EveryButtonNameRoundTripsAndAnUnknownOneIsRefused) {
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b) {
        EXPECT_EQ(parse_button(button_name(b), nullptr), b) << button_name(b);
    }
    EXPECT_EQ(parse_button("RightShoulder", nullptr), SDL_CONTROLLER_BUTTON_RIGHTSHOULDER);
    std::string why;
    EXPECT_FALSE(parse_button("turbo\x1b", &why));
    EXPECT_NE(why.find("unknown button 'turbo\\e'"), std::string::npos) << why;
    EXPECT_NE(why.find("rightshoulder"), std::string::npos) << why;
    EXPECT_EQ(buttons_label(default_pad_bindings(), Action::fire), "A, R1");
}

TEST(PadBindings, SettingsReadWriteAndReportBadEntriesAtTheirPosition) {
    const auto ok = parse_settings("[buttons]\nfire = [\"x\", \"leftshoulder\"]\npause = \"y\"\n",
                                   "settings.toml", {});
    EXPECT_TRUE(ok.errors.empty()) << ok.errors.front();
    EXPECT_EQ(ok.settings.buttons[static_cast<std::size_t>(Action::fire)],
              (std::vector<int>{SDL_CONTROLLER_BUTTON_X, SDL_CONTROLLER_BUTTON_LEFTSHOULDER}));
    EXPECT_EQ(ok.settings.buttons[static_cast<std::size_t>(Action::pause)],
              std::vector<int>{SDL_CONTROLLER_BUTTON_Y});
    // What is written reads back the same.
    const std::vector<std::string> presets = {"balanced"}, styles = {"vector"};
    const auto again =
        parse_settings(format_settings(ok.settings), "settings.toml", {presets, styles});
    EXPECT_TRUE(again.errors.empty()) << again.errors.front();
    EXPECT_EQ(again.settings.buttons, ok.settings.buttons);

    const auto bad = parse_settings(
        "[buttons]\nfire = [\"a\", \"banana\"]\njump = [\"b\"]\nback = [3]\n", "settings.toml", {});
    EXPECT_EQ(bad.errors.size(), 3u);
    auto any = [&bad](const std::string& needle) {
        return std::any_of(bad.errors.begin(), bad.errors.end(), [&](const std::string& e) {
            return e.find(needle) != std::string::npos;
        });
    };
    EXPECT_TRUE(any("settings.toml:2:14: error: fire: unknown button 'banana'"));
    EXPECT_TRUE(any("settings.toml:3:1: error: unknown action 'jump' in [buttons]"));
    EXPECT_TRUE(any("settings.toml:4:9: error: back: a button must be a string"));
    // Each bad action keeps its defaults.
    EXPECT_EQ(bad.settings.buttons, default_pad_bindings());
}

TEST(PadBindings, ButtonEventsFollowTheBindingsAndTheMenusKeepTheirButtons) {
    PadBindings buttons = default_pad_bindings();
    buttons[static_cast<std::size_t>(Action::fire)] = {SDL_CONTROLLER_BUTTON_X};
    buttons[static_cast<std::size_t>(Action::screenshot)] = {SDL_CONTROLLER_BUTTON_Y};
    buttons[static_cast<std::size_t>(Action::drive_forward)] = {SDL_CONTROLLER_BUTTON_LEFTSHOULDER};
    Input in(default_bindings(), GamepadMode::tank, buttons);
    // X fires now, held and tapped within a tick; A no longer fires but still confirms menus.
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_X, true));
    EXPECT_TRUE(in.state().fire);
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_X, false));
    EXPECT_TRUE(in.next_tick().fire);  // the tap was latched
    EXPECT_FALSE(in.next_tick().fire);
    in.take_menu_keys();
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_A, true));
    EXPECT_FALSE(in.state().fire);
    EXPECT_EQ(in.take_menu_keys(), std::vector<MenuKey>{MenuKey::confirm});
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_A, false));
    // A pressed action on a button: queued once.
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_Y, true));
    EXPECT_TRUE(has(in.take_pressed(), Action::screenshot));
    // A held drive action on a button drives both treads.
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true));
    EXPECT_EQ(in.state().left_tread, 1.0f);
    EXPECT_EQ(in.state().right_tread, 1.0f);
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, false));
    EXPECT_EQ(in.state().left_tread, 0.0f);
    // Start still pauses and starts (its default), and B still goes back.
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_START, true));
    const auto pressed = in.take_pressed();
    EXPECT_TRUE(has(pressed, Action::pause));
    EXPECT_TRUE(has(pressed, Action::start));
}

TEST(PadBindings, ACapturedButtonBindsAndDoesNothingElse) {
    Input in;
    in.begin_capture();
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_A, true));
    EXPECT_FALSE(in.capturing());
    EXPECT_EQ(in.take_captured_button(), SDL_CONTROLLER_BUTTON_A);
    EXPECT_FALSE(in.take_captured());
    EXPECT_TRUE(in.take_menu_keys().empty());  // not also a menu confirm
    EXPECT_TRUE(in.take_pressed().empty());
    in.handle_event(pad_button(SDL_CONTROLLER_BUTTON_A, false));
    EXPECT_FALSE(in.next_tick().fire);  // nor a shot
}

}  // namespace
}  // namespace bz::platform
