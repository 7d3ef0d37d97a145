#include "platform/bindings.h"

#include <SDL_scancode.h>
#include <gtest/gtest.h>

namespace bz::platform {
namespace {

TEST(Bindings, ParsesPlainAndModifiedKeys) {
    std::string why;
    const auto q = parse_key("Q", &why);
    ASSERT_TRUE(q) << why;
    EXPECT_EQ(q->scancode, SDL_SCANCODE_Q);
    EXPECT_EQ(q->mods, kModNone);

    const auto alt_enter = parse_key("alt+Return", &why);
    ASSERT_TRUE(alt_enter) << why;
    EXPECT_EQ(alt_enter->scancode, SDL_SCANCODE_RETURN);
    EXPECT_EQ(alt_enter->mods, kModAlt);

    const auto combo = parse_key("Ctrl+Shift+F5", &why);
    ASSERT_TRUE(combo) << why;
    EXPECT_EQ(combo->mods, kModCtrl | kModShift);

    // '+' inside a key name is not a modifier separator.
    const auto kp_plus = parse_key("Keypad +", &why);
    ASSERT_TRUE(kp_plus) << why;
    EXPECT_EQ(kp_plus->scancode, SDL_SCANCODE_KP_PLUS);
    const auto space = parse_key("space", &why);  // SDL's lookup ignores case
    ASSERT_TRUE(space) << why;
    EXPECT_EQ(space->scancode, SDL_SCANCODE_SPACE);
}

TEST(Bindings, RejectsUnknownKeysWithAReason) {
    std::string why;
    EXPECT_FALSE(parse_key("Banana", &why));
    EXPECT_NE(why.find("Banana"), std::string::npos);
    EXPECT_FALSE(parse_key("", &why));
    EXPECT_FALSE(parse_key("Alt+", &why));
    EXPECT_FALSE(parse_key("Alt+Nope", &why));
}

TEST(Bindings, NamesRoundTrip) {
    const Bindings b = default_bindings();
    for (std::size_t i = 0; i < kActionCount; ++i) {
        EXPECT_FALSE(b[i].empty()) << action_name(static_cast<Action>(i)) << " has no default key";
        for (const auto& k : b[i]) {
            std::string why;
            const auto again = parse_key(key_name(k), &why);
            ASSERT_TRUE(again) << key_name(k) << ": " << why;
            EXPECT_EQ(*again, k) << key_name(k);
        }
    }
    for (std::size_t i = 0; i < kActionCount; ++i) {
        const auto a = static_cast<Action>(i);
        EXPECT_EQ(action_from_name(action_name(a)), a);
    }
    EXPECT_FALSE(action_from_name("jump"));
}

TEST(Bindings, DefaultsMatchTheManual) {
    const Bindings b = default_bindings();
    auto has = [&b](Action a, const char* name) {
        const auto k = parse_key(name, nullptr);
        const auto& keys = b[static_cast<std::size_t>(a)];
        return k && std::find(keys.begin(), keys.end(), *k) != keys.end();
    };
    EXPECT_TRUE(has(Action::left_tread_forward, "Q"));
    EXPECT_TRUE(has(Action::left_tread_back, "A"));
    EXPECT_TRUE(has(Action::right_tread_forward, "E"));
    EXPECT_TRUE(has(Action::right_tread_back, "D"));
    EXPECT_TRUE(has(Action::drive_forward, "Up"));
    EXPECT_TRUE(has(Action::drive_back, "Down"));
    EXPECT_TRUE(has(Action::turn_left, "Left"));
    EXPECT_TRUE(has(Action::turn_right, "Right"));
    EXPECT_TRUE(has(Action::fire, "Space"));
    EXPECT_TRUE(has(Action::fire, "Left Ctrl"));
    EXPECT_TRUE(has(Action::pause, "P"));
    EXPECT_TRUE(has(Action::pause, "Escape"));
    EXPECT_TRUE(has(Action::fullscreen, "F11"));
    EXPECT_TRUE(has(Action::fullscreen, "Alt+Return"));
    EXPECT_TRUE(has(Action::screenshot, "F12"));
    EXPECT_TRUE(has(Action::vector_screenshot, "Shift+F12"));
    EXPECT_TRUE(has(Action::reload_shaders, "F5"));
    EXPECT_TRUE(has(Action::mute, "M"));
    EXPECT_TRUE(has(Action::volume_up, "Keypad +"));
    EXPECT_TRUE(has(Action::volume_down, "-"));
    EXPECT_TRUE(has(Action::start, "Return"));
    EXPECT_TRUE(has(Action::back, "Backspace"));
    EXPECT_TRUE(has(Action::quit, "F10"));
}

}  // namespace
}  // namespace bz::platform
