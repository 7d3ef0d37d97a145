#pragma once
// The player's settings file (TOML, in the pref folder). A bad value is reported as
// `file:line:col: error: ...` and that key keeps its default; a broken file keeps them all.
// Nothing in here may crash on what a person typed.
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "platform/bindings.h"
#include "platform/gl_context.h"
#include "platform/input.h"
#include "platform/pad_bindings.h"

namespace bz::platform {

// The 1980 machine's DIP switches (its operator manual): tanks at the start, the score from
// which missiles come, and the first bonus tank (the second always at 100,000). Unset: the
// level's own rule. A bonus score of 0 is the switch setting "no bonus tank".
struct ArcadeDips {
    std::optional<int> lives;          // 2..5
    std::optional<int> missile_score;  // 5000, 10000, 20000 or 30000
    std::optional<int> bonus_score;    // 0 (none), 15000, 20000 or 50000
    bool any() const { return lives || missile_score || bonus_score; }
    bool operator==(const ArcadeDips&) const = default;
};
inline constexpr int kDipLives[] = {2, 3, 4, 5};
inline constexpr int kDipMissileScores[] = {5000, 10000, 20000, 30000};
inline constexpr int kDipBonusScores[] = {0, 15000, 20000, 50000};
inline constexpr int kDipSecondBonus = 100000;

// Flicker, flashes and trails: "full" as designed, "soft" halved, "off" none (beam flicker,
// the overdriven flash of a hit or a cracked screen, phosphor trails).
inline const std::string kFlashLevels[] = {"full", "soft", "off"};

inline constexpr int kMinMaxFps = 20;
inline constexpr int kMaxMaxFps = 1000;
inline constexpr float kMinUiScale = 1.0f;
inline constexpr float kMaxUiScale = 2.0f;

// One step of the volume keys and of the Options row: both land on whole tenths.
inline constexpr float kVolumeStep = 0.1f;

struct Settings {
    Bindings keys = default_bindings();
    PadBindings buttons = default_pad_bindings();  // [buttons]: gamepad buttons per action
    float volume = 0.8f;                           // 0..1
    bool mute = false;
    Vsync vsync = Vsync::on;
    bool fullscreen = false;
    bool pause_on_focus_loss = true;
    std::string preset = "balanced";
    std::string style = "vector";  // a style name (scene/style.h)
    std::string beam = "mame";     // the vector beam's look: "mame" or "classic"
    bool overlay = false;          // Battlezone's red/green cabinet overlay
    bool hold_41hz = false;        // the original's ~41 Hz refresh, frames held
    std::string line_method;       // "compute", "geometry_shader", "auto" or empty: the preset's
    GamepadMode gamepad = GamepadMode::tank;
    bool show_fps = false;  // the frame-rate readout (toggled by its key too)
    // "easy", "normal" or "arcade"; "level" lets each level choose (its [enemies] difficulty).
    std::string difficulty = "level";
    std::string flashes = "full";  // one of kFlashLevels
    bool colour_safe = false;      // red shown as violet-blue: readable with red-green blindness
    float ui_scale = 1.0f;         // menu and HUD text, kMinUiScale..kMaxUiScale
    // Frames per second at most: 0 = the display's refresh rate when vsync is not in effect
    // (vsync paces the game otherwise); else this cap (kMinMaxFps..kMaxMaxFps) always.
    int max_fps = 0;
    ArcadeDips arcade;
};

struct SettingsLoad {
    Settings settings;
    std::vector<std::string> errors;  // one line each, ready to print
    bool file_existed = false;
    // Whether the file set a valid preset / style (else settings keeps the default): `play`
    // lets a level's preset fill in only where the player named none.
    bool preset_given = false;
    bool style_given = false;
    bool beam_given = false;
    // Only a file that loaded cleanly (or none at all) may be overwritten: a typo in the
    // user's file must not be "fixed" by silently replacing it with defaults.
    bool may_save() const { return errors.empty(); }
};

// The valid values of the keys whose names belong to other modules: `preset` (the renderer's
// presets) and `style` (the style table, scene/style.h, which platform may not link).
struct SettingsChoices {
    std::span<const std::string> presets;
    std::span<const std::string> styles;
};

SettingsLoad parse_settings(std::string_view toml_text, const std::string& source_name,
                            const SettingsChoices& choices);
SettingsLoad load_settings(const std::filesystem::path& file, const SettingsChoices& choices);

std::string format_settings(const Settings& s);  // a commented TOML document
void save_settings(const std::filesystem::path& file, const Settings& s);  // atomic

std::string_view vsync_name(Vsync v);
bool parse_vsync(std::string_view text, Vsync* out);

}  // namespace bz::platform
