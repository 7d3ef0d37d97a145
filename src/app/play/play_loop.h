#pragma once
// The interactive frame loop of `beamzone play`: events, fixed 60 Hz ticks with interpolated
// drawing, hot reload, overlays, screenshots, sound and the window-level keys.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "app/play/menu/play_menus.h"
#include "app/play/play_look.h"
#include "app/play/play_overlay.h"
#include "app/play/play_session.h"
#include "core/log.h"
#include "level/watcher.h"
#include "platform/audio.h"
#include "platform/gamepads.h"
#include "platform/gl_context.h"
#include "platform/input.h"
#include "platform/settings.h"
#include "render/renderer.h"

namespace bz::app {

// A key pressed by a script (--press) before frame `frame` (1-based) and released before
// `release_frame` (the same frame: a tap), through SDL's own event queue, so it takes the path
// a real key takes.
struct ScriptedKey {
    int frame = 1;
    int release_frame = 1;
    platform::KeyBinding key;
};

struct LoopConfig {
    int frames = 0;         // > 0: stop after this many frames, each exactly one tick long
    int screenshot_at = 0;  // > 0: take a screenshot on this frame (1-based)
    bool edit = false;      // free-fly camera controls instead of tank controls
    std::filesystem::path screenshots;
    std::vector<ScriptedKey> presses;
};

struct LoopParts {
    platform::GlContext& context;
    // The look for a level (nullptr: the built-in one); asked at the start and again after
    // every good reload, so the level's [render] section follows its edits.
    std::function<PlayLook(const level::Level* level)> look;
    // Makes the one renderer of the run. Sessions keep one mesh library for good (a reload
    // replaces meshes in it, bumping versions the renderer's cache notices), so it is never
    // made again.
    std::function<std::unique_ptr<render::Renderer>(const render::RenderSettings& settings,
                                                    int width, int height)>
        make_renderer;
    platform::Audio& audio;
    platform::Input& input;
    platform::Gamepads& gamepads;
    level::LevelWatcher* watcher;  // nullptr: the built-in level, nothing to watch
    PlayOverlay& overlay;
    Log& log;
    platform::Settings& settings;  // volume, mute and fullscreen changes are written back here
    const scene::VectorFont& font;
    // For the menus: the renderer's presets, the levels to choose from, where their preset and
    // style choices go, and how settings are saved (returns "" when saved, else why not).
    std::vector<std::string> presets;
    std::vector<menu::LevelChoice> levels;
    LookSources* look_sources = nullptr;
    std::function<std::string(const platform::Settings&)> save_settings;
    std::vector<std::string> settings_errors;           // shown on screen for a while at the start
    platform::Vsync vsync_given = platform::Vsync::on;  // what the driver gave at the start
};

struct LoopResult {
    int frames = 0;
    int ticks = 0;
    int gl_errors = 0;
    bool settings_changed = false;
    bool session_failed = false;
};

LoopResult run_play_loop(PlaySession& session, LoopParts& parts, const LoopConfig& config);

// Diagnostics as the overlay and the log show them.
std::vector<std::string> format_diagnostics(const std::vector<level::Diagnostic>& errors);

}  // namespace bz::app
