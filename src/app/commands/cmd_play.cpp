// `beamzone play`: the game in a window. Setup lives here; the frame loop is in play_loop.cpp
// and what is simulated and drawn in play_sessions.cpp.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "app/commands/commands.h"
#include "app/line_method_profile.h"
#include "app/play/menu/level_list.h"
#include "app/play/play_look.h"
#include "app/play/play_loop.h"
#include "app/play/play_sessions.h"
#include "app/play/play_usage.h"
#include "app/replay_level.h"
#include "cli/cli_args.h"
#include "cli/play_args.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/io/output_path.h"
#include "core/log.h"
#include "core/paths.h"
#include "core/text/printable.h"
#include "game/default_level.h"
#include "game/records/replay.h"
#include "level/loader.h"
#include "platform/pref_paths.h"
#include "render/settings.h"
#include "scene/style_table.h"

namespace bz::app {

namespace {

bool offscreen_allowed(const PlayOptions& o) {
    const char* env = std::getenv("BEAMZONE_ALLOW_OFFSCREEN");
    return o.headless_test || (env && std::strcmp(env, "1") == 0);
}

struct Play {
    const PlayOptions& options;
    const platform::PrefPaths& paths;
    Log& log;

    int run() {
        if (!options.record.empty()) {
            // Checked before anything starts, so a game is never played into a recording that
            // cannot be saved or that would replace the level, a setting or a high score.
            const std::filesystem::path inputs[] = {options.level,  level::default_level_path(),
                                                    paths.settings, paths.high_scores,
                                                    paths.log,      paths.gamepad_db};
            check_output_file("--record", options.record, kReplayOutput, inputs);
        }
        log.info("settings: " + paths.settings.string());
        log.info("high scores: " + paths.high_scores.string());
        log.info("log: " + paths.log.string());

        platform::SettingsLoad loaded = platform::load_settings(
            paths.settings, {render::preset_names(), scene::accepted_style_name_strings()});
        for (const auto& e : loaded.errors) log.warn(e);
        platform::Settings& settings = loaded.settings;
        if (!loaded.file_existed) save(settings);  // a commented file to edit, on first start
        // Command-line choices stay out of `settings`: it is saved back when the player changes
        // the volume or the window mode, and they are for this run only.
        const platform::Vsync wanted_vsync = options.vsync.value_or(settings.vsync);
        const bool fullscreen = options.fullscreen.value_or(settings.fullscreen);
        LookSources look;
        look.cli_style = options.style;
        look.cli_preset = options.preset;
        // The file just written on first start names the defaults; count them, so that the
        // first run looks like every later one.
        look.settings_style = settings.style;
        look.settings_style_given = loaded.style_given || !loaded.file_existed;
        if (loaded.preset_given || !loaded.file_existed) look.settings_preset = settings.preset;
        look.cli_beam = options.beam;
        if (loaded.beam_given || !loaded.file_existed) look.settings_beam = settings.beam;
        look.settings_overlay = settings.overlay;
        look.settings_hold_41hz = settings.hold_41hz;
        look.flashes = settings.flashes;
        look.colour_safe = settings.colour_safe;
        look.cli_line_method = options.line_method;
        if (!settings.line_method.empty()) look.settings_line_method = settings.line_method;

        // A replay names its level: without a LEVEL argument, play it on that one (the
        // built-in level included), as `replay --verify` does.
        std::string level_arg = options.level;
        bool replay_on_builtin = false;
        if (level_arg.empty() && !options.replay.empty()) {
            const std::string recorded = game::replay::load(options.replay).header.level;
            if (recorded == game::kBuiltinLevelName) {
                replay_on_builtin = true;
            } else {
                level_arg = replay_level_path(recorded, options.replay).string();
            }
        }

        // The level before the window, so a broken level file fails fast and plainly.
        log.info("data: " + project_root().string() + " (" + project_root_origin() + ")");
        std::unique_ptr<level::LevelWatcher> watcher;
        const std::filesystem::path level_path =
            level_arg.empty() ? level::default_level_path() : std::filesystem::path(level_arg);
        std::error_code ec;
        if (!replay_on_builtin && (!level_arg.empty() || std::filesystem::exists(level_path, ec))) {
            watcher = std::make_unique<level::LevelWatcher>(level_path);
            if (!watcher->current()) {
                for (const auto& line : format_diagnostics(watcher->errors())) {
                    std::fprintf(stderr, "%s\n", line.c_str());
                }
                const auto n = watcher->errors().size();
                log.error("cannot play " + printable(level_path.string()) + ": " +
                          std::to_string(n) + (n == 1 ? " error" : " errors") + " above");
                return 1;
            }
            log.info("level: " + printable(level_path.string()) + " (edits reload while playing)");
        } else if (replay_on_builtin) {
            log.info("the replay was recorded on the built-in level; playing it there");
        } else {
            log.info("no " + printable(level_path.string()) + "; playing the built-in level");
        }
        const level::Level* lvl = watcher ? &*watcher->current() : nullptr;

        platform::ContextOptions co;
        // A test run (offscreen allowed) uses a hidden window; players get a real one.
        co.mode = offscreen_allowed(options) ? platform::WindowMode::hidden
                  : fullscreen               ? platform::WindowMode::fullscreen_desktop
                                             : platform::WindowMode::windowed;
        if (co.mode == platform::WindowMode::hidden) {
            co.width = 640;  // a test run: a smaller frame keeps software GL quick
            co.height = 360;
        }
        if (options.size) {
            co.width = options.size->x;
            co.height = options.size->y;
        }
        co.title = "beamzone";
        // Synchronous GL debug output costs time; test runs want it, players do not.
        co.debug = options.frames > 0 || std::getenv("BEAMZONE_GL_DEBUG") != nullptr;
        platform::GlContext context(co);
        log.info("OpenGL renderer: " + context.renderer_name());
        const platform::Vsync vsync = context.set_vsync(wanted_vsync);
        if (vsync != wanted_vsync) {
            log.info("vsync " + std::string(platform::vsync_name(wanted_vsync)) +
                     " is not available; using " + std::string(platform::vsync_name(vsync)));
        }

        auto choose = [&look](const level::Level* current) { return choose_look(look, current); };
        // LineMethod::automatic's crossing, measured once per machine and kept.
        const LineMethodProfile line_methods =
            line_method_profile(paths.line_methods, Calibration::measure_if_missing);
        log.info(line_methods.describe());
        auto make_renderer = [threshold = line_methods.threshold()](const render::RenderSettings& r,
                                                                    int w, int h) {
            render::RenderSettings with_threshold = r;
            with_threshold.auto_compute_from_triangles = threshold;
            return std::make_unique<render::Renderer>(with_threshold, w, h, gl::TimingMethod::off);
        };

        platform::Audio audio(log, settings.volume, settings.mute);
        platform::Gamepads gamepads(log, data_dir() / "gamecontrollerdb" / "gamecontrollerdb.txt",
                                    paths.gamepad_db);
        platform::Input input(settings.keys, settings.gamepad, settings.buttons);
        const scene::VectorFont font = scene::VectorFont::load_default();
        PlayOverlay overlay(font);

        SessionOptions so;
        so.level = lvl;
        so.seed = options.seed;
        // --difficulty, else the settings file's unless it says "level", else the level's.
        so.difficulty = options.difficulty.value_or(
            settings.difficulty == "level" ? std::string() : settings.difficulty);
        so.arcade = arcade_rules(settings.arcade);
        so.record = options.record;
        so.replay = options.replay;
        so.high_scores = paths.high_scores;
        so.pause_on_focus_loss = settings.pause_on_focus_loss;
        so.font = &font;
        so.hints = screen_hints(settings.keys);
        std::unique_ptr<PlaySession> session =
            options.edit ? make_edit_session(so, log) : make_game_session(so, log);

        for (const std::string& notice : session->take_notices()) overlay.notify(notice, 10.0);

        LoopConfig config;
        config.frames = options.frames;
        config.screenshot_at = options.screenshot_at;
        config.edit = options.edit;
        config.screenshots = paths.screenshots;
        for (const ScriptedPress& p : options.presses) {
            config.presses.push_back({p.frame, p.release_frame, p.key});
        }
        // The menus save at once; never over a file that did not load cleanly.
        auto save_settings = [this, &loaded](const platform::Settings& s) -> std::string {
            if (!loaded.may_save()) {
                return "NOT SAVED: SETTINGS.TOML HAS ERRORS TO FIX FIRST (SEE THE LOG)";
            }
            return save(s) ? std::string() : "NOT SAVED: SEE THE LOG";
        };
        LoopParts parts{
            .context = context,
            .look = choose,
            .make_renderer = make_renderer,
            .audio = audio,
            .input = input,
            .gamepads = gamepads,
            .watcher = watcher.get(),
            .overlay = overlay,
            .log = log,
            .settings = settings,
            .font = font,
            .presets = render::preset_names(),
            .levels = menu::find_levels(level::default_level_path().parent_path(), paths.levels),
            .look_sources = &look,
            .save_settings = save_settings,
            .settings_errors = loaded.errors,
            .vsync_given = vsync,
        };
        // From here on a signal ends the loop, and what must be saved is saved below.
        stop_gracefully_on_signal();
        const LoopResult result = run_play_loop(*session, parts, config);
        const bool saved = session->save_on_exit();  // before we report
        session.reset();

        if (result.settings_changed) {
            if (loaded.may_save()) {
                save(settings);
            } else {
                log.warn("not saving settings: " + paths.settings.string() +
                         " has errors to fix first");
            }
        }
        if (options.frames > 0) {
            std::printf("play: %d frames, %d ticks, %d GL errors\n", result.frames, result.ticks,
                        result.gl_errors);
        }
        if (interrupt_requested()) {
            // Asked to quit, the game quit cleanly, as when its window is closed.
            log.info("stopped by a signal; what needed saving was saved");
        }
        return result.gl_errors > 0 || result.session_failed || !saved ? 1 : 0;
    }

    bool save(const platform::Settings& s) {
        try {
            platform::save_settings(paths.settings, s);
            return true;
        } catch (const UserError& e) {
            log.warn(std::string("cannot save settings: ") + e.what());
            return false;
        }
    }
};

}  // namespace

int cmd_play(Args args) {
    PlayOptions options;
    try {
        options = parse_play_options(static_cast<int>(args.size()), args.data());
    } catch (const UsageError& e) {
        std::fprintf(stderr, "beamzone play: %s\n", printable_message(e.what()).c_str());
        return 2;
    }
    const platform::PrefPaths paths = platform::pref_paths();
    if (options.help) {
        std::fputs(play_usage(paths.settings.string(), paths.high_scores.string()).c_str(), stdout);
        return 0;
    }

    std::string why;
    if (!platform::display_available(&why)) {
        if (!offscreen_allowed(options)) {
            std::fprintf(
                stderr,
                "beamzone: no display available (%s); try `beamzone render` for headless images\n",
                why.c_str());
            return 1;
        }
        setenv("SDL_VIDEODRIVER", "offscreen", 0);  // a test run: a hidden window is enough
    } else if (!offscreen_allowed(options)) {
        // DISPLAY may name a display SDL cannot reach; it then falls back to a driver that
        // shows nothing, and a game nobody can see would run until killed.
        const std::string driver = platform::start_video();
        if (platform::is_invisible_driver(driver)) {
            std::fprintf(stderr,
                         "beamzone: no display available (SDL could only start its '%s' video "
                         "driver); try `beamzone render` for headless images\n",
                         driver.c_str());
            return 1;
        }
    }

    Log log(paths.log);
    try {
        return Play{options, paths, log}.run();
    } catch (const std::exception& e) {
        log.error(std::string(e.what()) + " (log: " + paths.log.string() + ")");
        return 1;
    }
}

}  // namespace bz::app
