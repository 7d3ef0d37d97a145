#include "app/play/play_loop.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "app/play/frame_comfort.h"
#include "app/play/frame_pacer.h"
#include "app/play/frame_stats.h"
#include "app/play/play_sessions.h"
#include "app/vector_export.h"
#include "core/error.h"
#include "game/fixed_step.h"
#include "game/hud/hud_layout.h"
#include "platform/screenshot.h"
#include "scene/presentation_clock.h"
#include "scene/style.h"

namespace bz::app {

namespace {

// How often the level files are checked for edits (a stat per file: cheap, but not free).
constexpr double kReloadPollSeconds = 0.25;
// Settings errors are shown this long at the start (and stay in the log); the file is the
// player's to fix, the game goes on with defaults.
constexpr double kSettingsErrorSeconds = 30.0;

class Loop {
  public:
    Loop(PlaySession& session, LoopParts& parts, const LoopConfig& config)
        : session_(session),
          p_(parts),
          config_(config),
          watcher_(parts.watcher),
          menus_(menu_env()),
          vsync_given_(parts.vsync_given) {}

    LoopResult run() {
        if (watcher_) last_generation_ = watcher_->generation();
        if (!p_.settings_errors.empty()) {
            p_.overlay.set_errors(ErrorKind::settings, p_.settings_errors, kSettingsErrorSeconds);
        }
        applied_ = p_.settings;
        session_.set_text_scale(p_.settings.ui_scale);
        p_.overlay.set_text_scale(p_.settings.ui_scale);
        look_ = look_now();
        p_.log.info("look: " + look_.summary);
        int w = 0, h = 0;
        p_.context.drawable_size(w, h);
        renderer_ = p_.make_renderer(look_.render, std::max(w, 1), std::max(h, 1));
        std::uint64_t last_counter = SDL_GetPerformanceCounter();
        const double counter_hz = static_cast<double>(SDL_GetPerformanceFrequency());
        while (running_) {
            const std::uint64_t now = SDL_GetPerformanceCounter();
            double dt = static_cast<double>(now - last_counter) / counter_hz;
            last_counter = now;
            // A test run steps exactly one tick per frame, so it does the same work on any machine.
            if (result_.frames > 0) frame_stats_.add(dt);  // the first has no start
            if (config_.frames > 0) dt = game::FixedStep::kTickSeconds;

            push_scripted_keys();
            pump_events();
            // Menus first: while one is open, the keys that also pause or start the game are
            // its keys, not the game's.
            const bool menu_open = update_menus();
            for (const platform::Action a : p_.input.take_pressed()) on_action(a, menu_open);
            poll_reload(dt);
            simulate(dt);
            p_.overlay.advance(dt);
            clock_.advance(dt);  // the look's time runs on through pause, menus and --edit
            if (!minimized_ || config_.frames > 0) draw();
            pace(now);  // also keeps a minimised window from spinning
            ++result_.frames;
            if (config_.frames > 0 && result_.frames >= config_.frames) running_ = false;
            if (session_.finished()) running_ = false;
        }
        p_.audio.set_engine(false, 0.0f);
        p_.log.info(frame_stats_.summary());
        result_.session_failed = session_.failed();
        return result_;
    }

  private:
    void pump_events() {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            p_.gamepads.handle_event(e);
            p_.input.handle_event(e);
            switch (e.type) {
                case SDL_QUIT:
                    running_ = false;
                    break;
                case SDL_WINDOWEVENT:
                    if (e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) session_.on_focus_lost();
                    if (e.window.event == SDL_WINDOWEVENT_MINIMIZED ||
                        e.window.event == SDL_WINDOWEVENT_HIDDEN) {
                        minimized_ = true;
                    }
                    if (e.window.event == SDL_WINDOWEVENT_RESTORED ||
                        e.window.event == SDL_WINDOWEVENT_SHOWN) {
                        minimized_ = false;
                    }
                    break;
                case SDL_MOUSEBUTTONDOWN:
                    if (config_.edit && e.button.button == SDL_BUTTON_RIGHT)
                        SDL_SetRelativeMouseMode(SDL_TRUE);
                    if (e.button.button == SDL_BUTTON_LEFT) {
                        pointer_events_.push_back({Pointer::click, e.button.x, e.button.y});
                    } else if (e.button.button == SDL_BUTTON_RIGHT ||
                               e.button.button == SDL_BUTTON_X1) {
                        pointer_events_.push_back({Pointer::back, e.button.x, e.button.y});
                    }
                    break;
                case SDL_MOUSEWHEEL: {
                    int x = 0, y = 0;
                    SDL_GetMouseState(&x, &y);
                    const int dy =
                        e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y;
                    for (int i = 0; i < std::min(std::abs(dy), 5); ++i) {
                        pointer_events_.push_back(
                            {dy > 0 ? Pointer::wheel_up : Pointer::wheel_down, x, y});
                    }
                    break;
                }
                case SDL_MOUSEBUTTONUP:
                    if (config_.edit && e.button.button == SDL_BUTTON_RIGHT)
                        SDL_SetRelativeMouseMode(SDL_FALSE);
                    break;
                case SDL_MOUSEMOTION:
                    pointer_events_.push_back({Pointer::move, e.motion.x, e.motion.y});
                    if (config_.edit && (e.motion.state & SDL_BUTTON_RMASK)) {
                        mouse_dx_ += static_cast<float>(e.motion.xrel);
                        mouse_dy_ += static_cast<float>(e.motion.yrel);
                    }
                    break;
                default:
                    break;
            }
        }
    }

    // Waits out the rest of the frame the pacer asks for (frame_pacer.h): no busy idling
    // without vsync, in menus, in pause or while the window is hidden.
    void pace(std::uint64_t frame_start) {
        PaceInput in;
        in.test_run = config_.frames > 0;
        in.vsync_in_effect = vsync_given_ != platform::Vsync::off;
        in.max_fps = p_.settings.max_fps;
        if (result_.frames % 60 == 0) display_hz_ = display_hz();
        in.display_hz = display_hz_;
        const menu::Context c = session_.menu_context();
        in.scene = minimized_                   ? PaceScene::hidden
                   : c == menu::Context::paused ? PaceScene::paused
                   : c == menu::Context::title  ? PaceScene::title_menu
                                                : PaceScene::play;
        const double want = min_frame_seconds(in);
        if (want <= 0.0) return;
        const double spent = static_cast<double>(SDL_GetPerformanceCounter() - frame_start) /
                             static_cast<double>(SDL_GetPerformanceFrequency());
        const double left_ms = (want - spent) * 1000.0;
        if (left_ms >= 1.0) SDL_Delay(static_cast<Uint32>(left_ms));
    }

    int display_hz() const {
        SDL_DisplayMode mode{};
        const int index = SDL_GetWindowDisplayIndex(p_.context.window());
        if (index < 0 || SDL_GetCurrentDisplayMode(index, &mode) != 0) return 0;
        return mode.refresh_rate;
    }

    menu::Env menu_env() const {
        menu::Env env;
        env.settings = &p_.settings;
        env.presets = p_.presets;
        env.levels = p_.levels;
        if (watcher_) env.current_level = watcher_->file();
        env.vsync_given = p_.vsync_given;
        env.high_scores = session_.high_scores();
        env.high_scores_level = session_.high_scores_level();
        return env;
    }

    void push_scripted_keys() {
        const int frame = result_.frames + 1;
        for (const ScriptedKey& k : config_.presses) {
            if (k.frame != frame && k.release_frame != frame) continue;
            unsigned mod = KMOD_NONE;
            if (k.key.mods & platform::kModAlt) mod |= KMOD_LALT;
            if (k.key.mods & platform::kModCtrl) mod |= KMOD_LCTRL;
            if (k.key.mods & platform::kModShift) mod |= KMOD_LSHIFT;
            for (const Uint32 type : {SDL_KEYDOWN, SDL_KEYUP}) {
                if (type == SDL_KEYDOWN && k.frame != frame) continue;
                if (type == SDL_KEYUP && k.release_frame != frame) continue;
                SDL_Event e{};
                e.type = type;
                e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
                e.key.keysym.scancode = static_cast<SDL_Scancode>(k.key.scancode);
                e.key.keysym.mod = static_cast<Uint16>(mod);
                SDL_PushEvent(&e);
            }
        }
    }

    // Opens the menu the session's screen calls for and feeds it this frame's menu keys.
    // Returns whether a menu had the keys this frame.
    bool update_menus() {
        menus_.env().high_scores = session_.high_scores();
        menus_.env().high_scores_level = session_.high_scores_level();
        menus_.env().score_at_stake = session_.score_at_stake();
        menus_.env().score_qualifies = session_.score_qualifies();
        menus_.set_context(session_.menu_context());
        const bool open = menus_.open();
        std::vector<menu::Request> requests;
        if (menus_.capturing()) {
            if (const auto key = p_.input.take_captured()) {
                requests = menus_.captured(*key);
            } else if (const auto button = p_.input.take_captured_button()) {
                requests = menus_.captured_button(*button);
            }
        } else if (p_.input.capturing()) {
            p_.input.cancel_capture();  // the menu closed under it
        }
        for (const platform::MenuKey k : p_.input.take_menu_keys()) {
            if (!open) continue;  // in play the same keys drive the tank
            for (const menu::Request& r : menus_.handle(k)) requests.push_back(r);
        }
        // The mouse, in the order it happened since the last frame (menus are outside the
        // fixed-step simulation: nothing here is sampled per tick).
        for (const PointerEvent& e : std::exchange(pointer_events_, {})) {
            if (!open || config_.edit) continue;
            for (const menu::Request& r :
                 menus_.pointer(e.what, hud_point(e.x, e.y), p_.font, hud_aspect())) {
                requests.push_back(r);
            }
        }
        for (const menu::Request& r : requests) on_request(r);
        return open;
    }

    // Window points (mouse coordinates) as HUD units: origin at the centre, y up, the
    // screen's half height one unit.
    glm::vec2 hud_point(int x, int y) const {
        int w = 0, h = 0;
        SDL_GetWindowSize(p_.context.window(), &w, &h);
        if (w <= 0 || h <= 0) return {0.0f, 0.0f};
        const auto a = static_cast<float>(hud_aspect());
        return {(2.0f * static_cast<float>(x) / static_cast<float>(w) - 1.0f) * a,
                1.0f - 2.0f * static_cast<float>(y) / static_cast<float>(h)};
    }
    double hud_aspect() const {
        return renderer_
                   ? static_cast<double>(renderer_->width()) / std::max(1, renderer_->height())
                   : 16.0 / 9.0;
    }

    void on_request(const menu::Request& r) {
        using Kind = menu::Request::Kind;
        using Command = PlaySession::MenuCommand;
        switch (r.kind) {
            case Kind::start_game:
                session_.menu_command(Command::start_game);
                break;
            case Kind::resume:
                session_.menu_command(Command::resume);
                break;
            case Kind::quit_to_title:
                session_.menu_command(Command::quit_to_title);
                break;
            case Kind::quit:
                running_ = false;
                break;
            case Kind::choose_level:
                choose_level(r.level);
                break;
            case Kind::settings_changed:
                apply_settings();
                break;
            case Kind::begin_capture:
                p_.input.begin_capture();
                break;
        }
    }

    // A level from the title menu: loaded and watched like the one named on the command line.
    void choose_level(const std::filesystem::path& file) {
        auto w = std::make_unique<level::LevelWatcher>(file);
        if (!w->current()) {
            level_errors_ = format_diagnostics(w->errors());
            for (const auto& line : level_errors_) p_.log.warn(line);
            show_errors();
            return;
        }
        try {
            session_.level_changed(*w->current());
        } catch (const std::exception& e) {
            p_.log.warn(e.what());
            level_errors_ = {e.what()};
            show_errors();
            return;
        }
        chosen_watcher_ = std::move(w);
        watcher_ = chosen_watcher_.get();
        last_generation_ = watcher_->generation();
        level_errors_.clear();
        model_errors_.clear();
        show_errors();
        update_look();
        menus_.env().current_level = file;
        p_.log.info("level: " + file.string() +
                    " (chosen in the menu; edits reload while playing)");
    }

    // Puts what the options page changed into effect, then saves it.
    void apply_settings() {
        platform::Settings& s = p_.settings;
        p_.audio.set_volume(s.volume);
        p_.audio.set_mute(s.mute);
        if (s.fullscreen != p_.context.fullscreen()) p_.context.set_fullscreen(s.fullscreen);
        if (s.vsync != applied_.vsync) {
            const platform::Vsync got = p_.context.set_vsync(s.vsync);
            menus_.env().vsync_given = got;
            vsync_given_ = got;
            if (got != s.vsync) {
                p_.overlay.notify("vsync " + std::string(platform::vsync_name(s.vsync)) +
                                  " is not available here");
            }
        }
        if (s.difficulty != applied_.difficulty || s.arcade != applied_.arcade) {
            // Like --difficulty: the menu's choice is the player's say for this run.
            session_.rules_changed(s.difficulty == "level" ? std::string() : s.difficulty,
                                   arcade_rules(s.arcade));
        }
        p_.input.set_bindings(s.keys);
        p_.input.set_pad_bindings(s.buttons);
        p_.input.set_gamepad_mode(s.gamepad);
        session_.set_text_scale(s.ui_scale);
        p_.overlay.set_text_scale(s.ui_scale);
        if (s.keys != applied_.keys) session_.keys_changed(s.keys);
        // A choice made in the menu is the player's say for this run, like the command line.
        if (p_.look_sources &&
            (s.preset != applied_.preset || s.style != applied_.style || s.beam != applied_.beam ||
             s.flashes != applied_.flashes || s.colour_safe != applied_.colour_safe)) {
            p_.look_sources->cli_preset = s.preset;
            p_.look_sources->cli_style = s.style;
            p_.look_sources->cli_beam = s.beam;
            p_.look_sources->flashes = s.flashes;
            p_.look_sources->colour_safe = s.colour_safe;
            update_look();
        }
        applied_ = s;
        result_.settings_changed = true;
        const std::string why_not = p_.save_settings ? p_.save_settings(s) : std::string();
        menus_.env().save_status = why_not;
    }

    void on_action(platform::Action a, bool menu_open) {
        using platform::Action;
        switch (a) {
            case Action::pause:
                // In --edit, Escape (pause) leaves: there is no game to pause.
                if (config_.edit) {
                    running_ = false;
                    break;
                }
                [[fallthrough]];
            case Action::start:
            case Action::back:
                if (!menu_open) session_.on_action(a);
                break;
            case Action::fullscreen: {
                p_.context.set_fullscreen(!p_.context.fullscreen());
                p_.settings.fullscreen = p_.context.fullscreen();
                applied_.fullscreen = p_.settings.fullscreen;
                result_.settings_changed = true;
                break;
            }
            case Action::show_fps:
                p_.settings.show_fps = !p_.settings.show_fps;
                applied_.show_fps = p_.settings.show_fps;
                result_.settings_changed = true;
                break;
            case Action::screenshot:
                screenshot_requested_ = true;
                break;
            case Action::vector_screenshot:
                vector_screenshot_requested_ = true;
                break;
            case Action::reload_shaders:
                reload_shaders();
                break;
            case Action::mute: {
                p_.settings.mute = !p_.settings.mute;
                p_.audio.set_mute(p_.settings.mute);
                p_.overlay.notify(p_.settings.mute ? "sound off" : "sound on");
                result_.settings_changed = true;
                break;
            }
            case Action::volume_up:
            case Action::volume_down: {
                const float step =
                    a == Action::volume_up ? platform::kVolumeStep : -platform::kVolumeStep;
                // Snap to whole steps so repeated presses land on 0% and 100% exactly.
                const float v = std::round((p_.settings.volume + step) / platform::kVolumeStep) *
                                platform::kVolumeStep;
                p_.settings.volume = std::clamp(v, 0.0f, 1.0f);
                p_.audio.set_volume(p_.settings.volume);
                p_.overlay.notify(
                    "volume " +
                    std::to_string(static_cast<int>(std::lround(p_.settings.volume * 100))) + "%" +
                    (p_.settings.mute ? " (muted: M)" : ""));
                result_.settings_changed = true;
                break;
            }
            case Action::quit:
                running_ = false;
                break;
            case Action::cycle_style: {
                // For this run only, like --style; a level reload keeps the chosen look.
                cycled_style_ = scene::next_style(look_.style);
                look_.style = *cycled_style_;
                const std::string name(scene::style_name(look_.style));
                p_.log.info("look: style " + name + " (play key)");
                p_.overlay.notify("style " + name);
                break;
            }
            default:
                break;
        }
    }

    const level::Level* current_level() const {
        return watcher_ && watcher_->current() ? &*watcher_->current() : nullptr;
    }

    // The look the settings, the level and the command line choose, with the session's rule
    // for the picture's past (--edit keeps none).
    PlayLook look_now() const {
        PlayLook look = p_.look(current_level());
        look.render.keep_history = session_.keeps_history();
        return look;
    }

    // After a good reload: the level's [render] section may have changed.
    void update_look() {
        PlayLook next = look_now();
        renderer_->set_settings(next.render);
        if (next.summary != look_.summary) p_.log.info("look: " + next.summary);
        look_ = std::move(next);
        if (cycled_style_) look_.style = *cycled_style_;
    }

    void reload_shaders() {
        std::string error;
        if (renderer_->reload_shaders(&error)) {
            shader_errors_.clear();
            p_.log.info("shaders reloaded");
            p_.overlay.notify("shaders reloaded");
        } else {
            p_.log.warn("shader reload failed, keeping the old shaders: " + error);
            shader_errors_ = {error};
        }
        show_errors();
    }

    void poll_reload(double dt) {
        if (!watcher_) return;
        since_poll_ += dt;
        if (since_poll_ < kReloadPollSeconds) return;
        since_poll_ = 0.0;
        if (!watcher_->poll()) return;
        level_errors_ = format_diagnostics(watcher_->errors());
        for (const auto& line : level_errors_) p_.log.warn(line);
        if (watcher_->generation() != last_generation_ && watcher_->current()) {
            last_generation_ = watcher_->generation();
            model_errors_.clear();
            try {
                session_.level_changed(*watcher_->current());
                update_look();
                p_.log.info("level reloaded: " + watcher_->file().string());
                p_.overlay.notify("level reloaded");
            } catch (const std::exception& e) {
                // The level validated but the game could not build it (say, a model that will
                // not import): keep the running world and say what is wrong with what.
                auto& list =
                    names_a_model(*watcher_->current(), e.what()) ? model_errors_ : level_errors_;
                list.push_back(e.what());
                p_.log.warn(e.what());
            }
        }
        show_errors();
    }

    // Whether a build error is about one of the level's model files (else the level itself).
    static bool names_a_model(const level::Level& lvl, const std::string& message) {
        for (const level::ObjectDesc& o : lvl.obstacles) {
            if (o.kind == "model" && !o.model.empty() &&
                message.find(o.model.filename().string()) != std::string::npos) {
                return true;
            }
        }
        return false;
    }

    void show_errors() {
        p_.overlay.set_errors(ErrorKind::level, level_errors_);
        p_.overlay.set_errors(ErrorKind::model, model_errors_);
        p_.overlay.set_errors(ErrorKind::shader, shader_errors_);
    }

    platform::FlyControls fly_controls() {
        platform::FlyControls c;
        if (!config_.edit) return c;
        auto key = [this](SDL_Scancode s) { return p_.input.key_held(s) ? 1.0f : 0.0f; };
        c.forward = key(SDL_SCANCODE_W) - key(SDL_SCANCODE_S);
        c.right = key(SDL_SCANCODE_D) - key(SDL_SCANCODE_A);
        c.up =
            key(SDL_SCANCODE_R) + key(SDL_SCANCODE_E) - key(SDL_SCANCODE_F) - key(SDL_SCANCODE_Q);
        c.yaw = key(SDL_SCANCODE_LEFT) - key(SDL_SCANCODE_RIGHT);
        c.pitch = key(SDL_SCANCODE_UP) - key(SDL_SCANCODE_DOWN);
        c.fast = p_.input.key_held(SDL_SCANCODE_LSHIFT) || p_.input.key_held(SDL_SCANCODE_RSHIFT);
        c.mouse_dx = std::exchange(mouse_dx_, 0.0f);
        c.mouse_dy = std::exchange(mouse_dy_, 0.0f);
        return c;
    }

    void simulate(double dt) {
        session_.update(fly_controls(), dt);
        const game::StepPlan plan = step_.advance(dt);
        // Each tick takes the presses latched since the one before, so a tap shorter than a
        // frame (or, at a low frame rate, than several ticks) is never lost.
        for (int i = 0; i < plan.ticks; ++i) session_.tick(p_.input.next_tick());
        result_.ticks += plan.ticks;
        alpha_ = plan.alpha;
        const SessionSounds sounds = session_.take_sounds();
        p_.audio.set_engine(sounds.engine_on, sounds.engine_speed);
        for (const SoundCue& s : sounds.events) p_.audio.play(s.sound, s.gain);
    }

    void draw() {
        int w = 0, h = 0;
        p_.context.drawable_size(w, h);  // pixels, not window points: right on HiDPI screens
        if (w > 0 && h > 0 && (w != renderer_->width() || h != renderer_->height())) {
            renderer_->resize(w, h);
        }
        const double aspect =
            static_cast<double>(renderer_->width()) / std::max(1, renderer_->height());
        scene::FrameList frame = session_.frame(alpha_, aspect);
        frame.style = look_.style;
        clock_.stamp(frame);
        if (!menus_.keeps_game_hud()) frame.hud.clear();
        for (scene::DrawItem& item : frame.items) item.intensity *= menus_.scene_intensity();
        // A menu's rows reach the notice strip at large text: its notices take the footer.
        p_.overlay.set_notice_place(menus_.open() ? PlayOverlay::NoticePlace::footer
                                                  : PlayOverlay::NoticePlace::strip);
        menus_.draw(
            frame.hud, p_.font, aspect, static_cast<std::uint64_t>(result_.frames),
            p_.overlay.notice_in_footer() ? menu::FooterLine::overlay : menu::FooterLine::hints);
        p_.overlay.set_footer(p_.settings.show_fps ? frame_stats_.readout() : std::string());
        // A menu over the screen shows its own one-line footer instead of the screen's.
        p_.overlay.set_footer_top(menus_.keeps_game_hud() ? session_.footer_top()
                                                          : game::hud::kFooterTop);
        p_.overlay.draw(frame.hud, aspect);
        apply_comfort(frame, p_.settings.flashes, p_.settings.colour_safe);
        if (result_.frames + 1 == config_.screenshot_at) screenshot_requested_ = true;
        if (screenshot_requested_) {
            // From the renderer's own image, not the window: a window system may not have
            // resized the window's buffer yet (or ever, without a window manager).
            screenshot_requested_ = false;
            renderer_->render(frame, session_.meshes(), render::Renderer::kOffscreen);
            take_screenshot();
        }
        if (vector_screenshot_requested_) {
            vector_screenshot_requested_ = false;
            take_vector_screenshot(frame);
        }
        renderer_->render(frame, session_.meshes(), 0);
        collect_gl_messages();
        p_.context.swap();
    }

    void take_screenshot() {
        try {
            const auto path =
                platform::save_screenshot(config_.screenshots, renderer_->width(),
                                          renderer_->height(), renderer_->read_color());
            p_.log.info("screenshot saved: " + path.string());
            p_.overlay.notify("screenshot " + path.filename().string());
        } catch (const std::exception& e) {
            p_.log.warn(std::string("screenshot failed: ") + e.what());
            p_.overlay.notify("screenshot failed (see the log)");
        }
    }

    // The frame's exact visible lines (and HUD) as SVG, numbered like the screenshots. The CPU
    // reference takes a moment on big scenes: the game pauses for it, once, on request.
    void take_vector_screenshot(const scene::FrameList& frame) {
        try {
            std::error_code ec;
            std::filesystem::create_directories(config_.screenshots, ec);
            if (ec) throw UserError("cannot create " + config_.screenshots.string());
            const auto path = platform::next_screenshot_path(config_.screenshots, ".svg");
            // The lines the look draws: its crease angle, material and intersection lines if
            // it asks.
            render::FrameSvgOptions svg;
            svg.reference.crease_angle_deg = look_.render.crease_angle_deg;
            svg.reference.material_lines = look_.render.material_lines;
            svg.reference.intersection_lines = look_.render.intersection_lines;
            const std::string line = export_frame_svg(path, frame, session_.meshes(),
                                                      renderer_->width(), renderer_->height(), svg);
            p_.log.info("vector screenshot saved: " + line);
            p_.overlay.notify("screenshot " + path.filename().string());
        } catch (const std::exception& e) {
            p_.log.warn(std::string("vector screenshot failed: ") + e.what());
            p_.overlay.notify("vector screenshot failed (see the log)");
        }
    }

    void collect_gl_messages() {
        auto& sink = p_.context.debug();
        if (sink.messages().empty() && sink.performance_hints().empty() && sink.error_count() == 0)
            return;
        for (const auto& m : sink.messages()) p_.log.warn("GL: " + m);
        for (const auto& m : sink.performance_hints()) p_.log.info("GL: " + m);
        result_.gl_errors += sink.error_count();
        sink.clear();
    }

    PlaySession& session_;
    LoopParts& p_;
    const LoopConfig& config_;
    level::LevelWatcher* watcher_;  // the command line's level, or the one chosen in the menu
    std::unique_ptr<level::LevelWatcher> chosen_watcher_;
    menu::PlayMenus menus_;
    platform::Settings applied_;  // the settings as last put into effect
    FrameStats frame_stats_;
    game::FixedStep step_;
    scene::PresentationClock clock_;  // phosphor, frame holding and flicker follow it
    std::unique_ptr<render::Renderer> renderer_;
    PlayLook look_;
    std::optional<scene::Style> cycled_style_;  // chosen with the cycle_style key
    LoopResult result_;
    bool running_ = true;
    bool minimized_ = false;
    bool screenshot_requested_ = false;
    bool vector_screenshot_requested_ = false;
    double alpha_ = 1.0;
    double since_poll_ = 0.0;
    std::uint64_t last_generation_ = 0;
    float mouse_dx_ = 0.0f, mouse_dy_ = 0.0f;
    using Pointer = menu::PlayMenus::Pointer;
    struct PointerEvent {
        Pointer what;
        int x = 0, y = 0;  // window points
    };
    std::vector<PointerEvent> pointer_events_;  // since the last frame, for the menus
    platform::Vsync vsync_given_;               // what the driver gave
    int display_hz_ = 0;
    std::vector<std::string> level_errors_;
    std::vector<std::string> model_errors_;
    std::vector<std::string> shader_errors_;
};

}  // namespace

std::vector<std::string> format_diagnostics(const std::vector<level::Diagnostic>& errors) {
    std::vector<std::string> lines;
    lines.reserve(errors.size());
    for (const auto& d : errors) lines.push_back(level::format(d));
    return lines;
}

LoopResult run_play_loop(PlaySession& session, LoopParts& parts, const LoopConfig& config) {
    return Loop(session, parts, config).run();
}

}  // namespace bz::app
