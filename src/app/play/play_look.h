#pragma once
// How `play` draws: the line style and the renderer settings, from the command line, the
// level's [render] section and the player's settings file.
//   style:  --style, else the level's style (part of its design), else the settings file
//   preset: --preset, else the settings file, else the level's preset (the player's machine
//           decides the speed a level can afford)
//   line width, crease angle, bloom strength: the level's, where it sets them
//   beam:   --beam, else the settings file, else the level's, else "mame"; the overlay and
//           the 41 Hz hold are on when the settings file or the level turns them on
#include <optional>
#include <string>

#include "level/level.h"
#include "render/settings.h"
#include "scene/frame_list.h"

namespace bz::app {

struct LookSources {
    std::optional<std::string> cli_style;
    std::optional<std::string> cli_preset;
    std::string settings_style = "vector";       // the settings file's, or its default
    bool settings_style_given = false;           // false: the file does not name one
    std::optional<std::string> settings_preset;  // none: the settings file does not name one
    std::optional<std::string> cli_beam;
    std::optional<std::string> settings_beam;  // none: the settings file does not name one
    bool settings_overlay = false;
    bool settings_hold_41hz = false;
    // Line method: --line-method, else the settings file, else the level, else the preset's.
    std::optional<std::string> cli_line_method;
    std::optional<std::string> settings_line_method;
    // The player's comfort settings: "full", "soft" or "off" beam flicker and phosphor trails
    // (the frame's flashes are frame_comfort.h's), and the colour-safe overlay.
    std::string flashes = "full";
    bool colour_safe = false;
};

struct PlayLook {
    scene::Style style = scene::Style::vector;
    render::RenderSettings render;
    // For the log, e.g. "style arcade (level), preset fast (command line), line width 3 px
    // (level)".
    std::string summary;
};

// `level` may be null (the built-in level). Throws UserError for a preset the renderer does
// not know (the level loader and the settings file already refuse those).
PlayLook choose_look(const LookSources& sources, const level::Level* level);

}  // namespace bz::app
