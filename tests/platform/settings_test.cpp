#include "platform/settings.h"

#include <SDL_scancode.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "platform/settings_test_util.h"

namespace bz::platform {
namespace {

namespace fs = std::filesystem;

using test::kPresets;
using test::kStyles;
using test::parse;

bool any_error_contains(const SettingsLoad& r, const std::string& needle) {
    for (const auto& e : r.errors) {
        if (e.find(needle) != std::string::npos) return true;
    }
    return false;
}

TEST(Settings, EmptyFileGivesDefaults) {
    const SettingsLoad r = parse("");
    EXPECT_TRUE(r.errors.empty());
    EXPECT_EQ(r.settings.volume, Settings{}.volume);
    EXPECT_EQ(r.settings.vsync, Vsync::on);
    EXPECT_EQ(r.settings.keys, default_bindings());
}

TEST(Settings, ReadsEveryKey) {
    const SettingsLoad r = parse(R"(
volume = 0.25
mute = true
vsync = "adaptive"
fullscreen = true
pause_on_focus_loss = false
preset = "high"
style = "arcade"
gamepad = "drive"
[keys]
fire = ["F", "Alt+G"]
pause = "Backspace"
mute = []
)");
    ASSERT_TRUE(r.errors.empty()) << r.errors.front();
    const Settings& s = r.settings;
    EXPECT_FLOAT_EQ(s.volume, 0.25f);
    EXPECT_TRUE(s.mute);
    EXPECT_EQ(s.vsync, Vsync::adaptive);
    EXPECT_TRUE(s.fullscreen);
    EXPECT_FALSE(s.pause_on_focus_loss);
    EXPECT_EQ(s.preset, "high");
    EXPECT_EQ(s.style, "arcade");
    EXPECT_EQ(s.gamepad, GamepadMode::drive);
    const auto& fire = s.keys[static_cast<std::size_t>(Action::fire)];
    ASSERT_EQ(fire.size(), 2u);
    EXPECT_EQ(fire[0].scancode, SDL_SCANCODE_F);
    EXPECT_EQ(fire[1].mods, kModAlt);
    EXPECT_EQ(s.keys[static_cast<std::size_t>(Action::pause)].size(), 1u);
    EXPECT_TRUE(s.keys[static_cast<std::size_t>(Action::mute)].empty());
    // Untouched actions keep their defaults.
    EXPECT_EQ(s.keys[static_cast<std::size_t>(Action::screenshot)],
              default_bindings()[static_cast<std::size_t>(Action::screenshot)]);
    EXPECT_EQ(parse("volume = 1").settings.volume, 1.0f);  // an integer is a number too
}

TEST(Settings, BadValuesReportPositionAndKeepDefaults) {
    const SettingsLoad r = parse(
        "volume = 3\n"
        "mute = \"yes\"\n"
        "vsync = \"sometimes\"\n"
        "preset = \"ultra\"\n"
        "style = 4\n"
        "colour = 1\n"
        "[keys]\n"
        "fire = [\"Space\", \"Banana\"]\n"
        "jump = [\"J\"]\n"
        "pause = [1]\n");
    const Settings d;
    EXPECT_EQ(r.settings.volume, d.volume);
    EXPECT_EQ(r.settings.mute, d.mute);
    EXPECT_EQ(r.settings.vsync, d.vsync);
    EXPECT_EQ(r.settings.preset, d.preset);
    EXPECT_EQ(r.settings.style, d.style);
    EXPECT_EQ(r.settings.keys, default_bindings());
    EXPECT_EQ(r.errors.size(), 9u);
    EXPECT_TRUE(
        any_error_contains(r, "settings.toml:1:10: error: volume must be a number from 0 to 1"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:2:8: error: mute must be true or false"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:3:"));
    EXPECT_TRUE(any_error_contains(r, "\"fast\", \"balanced\", \"high\""));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:6:1: error: unknown setting 'colour'"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:8:18: error: fire: unknown key 'Banana'"));
    EXPECT_TRUE(any_error_contains(r, "unknown action 'jump'"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:10:10: error: pause: a key must be a string"));
    EXPECT_FALSE(r.may_save());
    EXPECT_EQ(r.errors.front().rfind("settings.toml:1:", 0), 0u);  // sorted by position
    EXPECT_EQ(r.errors.back().rfind("settings.toml:10:", 0), 0u);
    for (const auto& e : r.errors) EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(Settings, LineMethodTakesAutoAndReportsABadOneAtItsPosition) {
    for (const std::string m : {"compute", "geometry_shader", "auto", "geometry"}) {
        const SettingsLoad r = parse("line_method = \"" + m + "\"\n");
        EXPECT_TRUE(r.errors.empty()) << m << ": " << (r.errors.empty() ? "" : r.errors.front());
        EXPECT_EQ(r.settings.line_method, m);
    }
    // Saved and read back as written.
    Settings s;
    s.line_method = "auto";
    EXPECT_EQ(parse(format_settings(s)).settings.line_method, "auto");

    const SettingsLoad bad = parse("volume = 0.5\nline_method = \"automatic\"\n");
    ASSERT_EQ(bad.errors.size(), 1u);
    const std::string& e = bad.errors.front();
    EXPECT_EQ(e.rfind("settings.toml:2:15: error: line_method must be one of ", 0), 0u) << e;
    EXPECT_NE(bad.errors.front().find("\"auto\""), std::string::npos) << bad.errors.front();
    EXPECT_EQ(bad.settings.line_method, Settings{}.line_method);
}

TEST(Settings, SyntaxErrorKeepsEverythingDefault) {
    const SettingsLoad r = parse("volume = 0.5\nmute = tru e\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].rfind("settings.toml:2:", 0), 0u) << r.errors[0];
    EXPECT_NE(r.errors[0].find("error:"), std::string::npos);
    EXPECT_EQ(r.settings.volume, Settings{}.volume);
}

TEST(Settings, HostileInputDoesNotCrash) {
    const std::vector<std::string> texts = {std::string("\x00\x01\x02", 3),
                                            "[[[[",
                                            "volume = nan",
                                            "volume = inf",
                                            "keys = 3",
                                            "[keys]\nfire = \"\"",
                                            "[keys]\nfire = [[\"Q\"]]",
                                            "vsync = [\"on\"]",
                                            "= = =",
                                            "\xff\xfe"};
    for (const std::string& text : texts) {
        const SettingsLoad r = parse(text);
        EXPECT_FALSE(r.errors.empty()) << text;
        EXPECT_EQ(r.settings.volume, Settings{}.volume) << text;
    }
}

TEST(Settings, FormatRoundTripsAndSavesAtomically) {
    Settings s;
    s.volume = 0.5f;
    s.mute = true;
    s.vsync = Vsync::off;
    s.preset = "fast";
    s.style = "arcade";
    s.gamepad = GamepadMode::drive;
    // Key names that need escaping in TOML strings: a backslash and a quote.
    const auto backslash = parse_key("\\", nullptr);
    const auto quote = parse_key("'", nullptr);
    ASSERT_TRUE(backslash && quote);
    s.keys[static_cast<std::size_t>(Action::fire)] = {*backslash, *quote};
    const fs::path dir = fs::temp_directory_path() / ("bz_settings_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "settings.toml";
    save_settings(file, s);
    const SettingsLoad r = load_settings(file, {kPresets, kStyles});
    ASSERT_TRUE(r.errors.empty()) << r.errors.front();
    EXPECT_TRUE(r.file_existed);
    EXPECT_EQ(r.settings.volume, 0.5f);
    EXPECT_TRUE(r.settings.mute);
    EXPECT_EQ(r.settings.vsync, Vsync::off);
    EXPECT_EQ(r.settings.preset, "fast");
    EXPECT_EQ(r.settings.style, "arcade");
    EXPECT_EQ(r.settings.gamepad, GamepadMode::drive);
    EXPECT_EQ(r.settings.keys, s.keys);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1u);  // no temp file left behind
    fs::remove_all(dir);
}

TEST(Settings, MissingFileIsNotAnError) {
    const SettingsLoad r =
        load_settings("/nonexistent/beamzone/settings.toml", {kPresets, kStyles});
    EXPECT_TRUE(r.errors.empty());
    EXPECT_FALSE(r.file_existed);
    EXPECT_TRUE(r.may_save());
}

TEST(Settings, UnreadableFileIsReported) {
    const SettingsLoad r = load_settings("/", {kPresets, kStyles});  // a folder, not a file
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_FALSE(r.may_save());
}

TEST(Settings, PlayerOptionsAndArcadeDipsRoundTrip) {
    Settings s;
    s.flashes = "off";
    s.colour_safe = true;
    s.ui_scale = 1.5f;
    s.max_fps = 144;
    s.arcade.lives = 5;
    s.arcade.missile_score = 30000;
    s.arcade.bonus_score = 0;  // the "no bonus tank" switch
    const SettingsLoad r = parse(format_settings(s));
    ASSERT_TRUE(r.errors.empty()) << r.errors.front();
    EXPECT_EQ(r.settings.flashes, "off");
    EXPECT_TRUE(r.settings.colour_safe);
    EXPECT_FLOAT_EQ(r.settings.ui_scale, 1.5f);
    EXPECT_EQ(r.settings.max_fps, 144);
    EXPECT_EQ(r.settings.arcade, s.arcade);
    // Unset switches stay unset (the level's rules), written as comments.
    const SettingsLoad d = parse(format_settings(Settings{}));
    ASSERT_TRUE(d.errors.empty()) << d.errors.front();
    EXPECT_FALSE(d.settings.arcade.any());
    EXPECT_NE(format_settings(Settings{}).find("# lives = 3"), std::string::npos);
}

TEST(Settings, BadPlayerOptionsAndDipsAreReportedAtTheirPosition) {
    const SettingsLoad r = parse(
        "ui_scale = 3\nflashes = \"dim\"\n[arcade]\nlives = 7\nmissile_score = 10000\n"
        "bonus_score = \"many\"\ncoins = 2\n");
    EXPECT_TRUE(
        any_error_contains(r, "settings.toml:1:12: error: ui_scale must be a number from 1 to 2"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:2:11: error: flashes must be one of"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:4:9: error: lives must be one of 2, 3, 4, 5"));
    EXPECT_TRUE(any_error_contains(r, "bonus_score must be one of 0, 15000, 20000, 50000"));
    EXPECT_TRUE(any_error_contains(r, "settings.toml:7:1: error: unknown arcade setting 'coins'"));
    EXPECT_FLOAT_EQ(r.settings.ui_scale, 1.0f);
    EXPECT_EQ(r.settings.flashes, "full");
    EXPECT_FALSE(r.settings.arcade.lives);
    EXPECT_EQ(r.settings.arcade.missile_score, 10000);  // the good one is kept
    EXPECT_FALSE(r.may_save());
    EXPECT_TRUE(
        any_error_contains(parse("max_fps = 5\n"), "settings.toml:1:11: error: max_fps must be 0"));
    // Not a table at all.
    EXPECT_TRUE(any_error_contains(parse("arcade = 3\n"), "arcade must be a table"));
}

}  // namespace
}  // namespace bz::platform
