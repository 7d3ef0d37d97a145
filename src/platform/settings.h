#pragma once
// The player's settings file (TOML, in the pref folder). A bad value is reported as
// `file:line:col: error: ...` and that key keeps its default; a broken file keeps them all.
// Nothing in here may crash on what a person typed.
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "platform/bindings.h"
#include "platform/gl_context.h"
#include "platform/input.h"

namespace bz::platform {

struct Settings {
    Bindings keys = default_bindings();
    float volume = 0.8f;  // 0..1
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
