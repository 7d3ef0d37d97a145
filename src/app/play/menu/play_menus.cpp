#include "app/play/menu/play_menus.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>

#include "core/budgets.h"
#include "core/text/ascii_case.h"
#include "scene/style.h"

namespace bz::app::menu {

namespace {

// A level's description under the list: past one menu line's worth, it breaks at the space
// nearest its middle onto two lines, so that it is read whole rather than shrunk or cut.
std::vector<std::string> two_lines(const std::string& text) {
    if (text.empty()) return {};
    if (text.size() <= 3 * budget::kMenuLabelChars / 2) return {text};
    const std::size_t mid = text.size() / 2;
    std::size_t best = std::string::npos;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != ' ') continue;
        const auto dist = [mid](std::size_t k) { return k > mid ? k - mid : mid - k; };
        if (best == std::string::npos || dist(i) < dist(best)) best = i;
    }
    if (best == std::string::npos) return {text};
    return {text.substr(0, best), text.substr(best + 1)};
}

using platform::Action;
using platform::MenuKey;

enum TitleRow : std::size_t { t_start, t_level, t_options, t_controls, t_scores, t_quit };
enum PauseRow : std::size_t { p_resume, p_options, p_controls, p_quit_to_title };
enum OptionRow : std::size_t {
    o_difficulty,
    o_preset,
    o_style,
    o_beam,
    o_volume,
    o_fullscreen,
    o_vsync,
    o_fps,
    o_max_fps,
    o_comfort,
    o_arcade,
    o_gamepad,
    o_keys,
    o_reset_keys,
    o_back
};
enum ComfortRow : std::size_t { c_ui_scale, c_flashes, c_colour_safe, c_back };
enum ArcadeRow : std::size_t { a_lives, a_missile, a_bonus, a_back };

// The options menu offers the style table's canonical names (scene/style.h), in F6's order.
std::vector<std::string> style_names() {
    std::vector<std::string> out;
    for (const scene::Style s : scene::all_styles()) out.emplace_back(scene::style_name(s));
    return out;
}

constexpr float kUiScaleStep = 0.25f;
const std::string kBeams[] = {"mame", "classic"};
constexpr int kFrameRateCaps[] = {0, 30, 60, 75, 120, 144, 240};  // 0: AUTO
const std::string kDifficulties[] = {"level", "easy", "normal", "arcade"};

std::string on_off(bool b) {
    return b ? "ON" : "OFF";
}

// The next of `values` after `current`, `by` steps on, wrapping.
std::string cycle(const std::vector<std::string>& values, const std::string& current, int by) {
    if (values.empty()) return current;
    const auto it = std::find(values.begin(), values.end(), current);
    const auto n = static_cast<int>(values.size());
    const int i = it == values.end() ? 0 : static_cast<int>(it - values.begin());
    return values[static_cast<std::size_t>(((i + by) % n + n) % n)];
}

std::string level_label(const Env& env) {
    if (env.current_level.empty()) return "BUILT-IN";
    for (const LevelChoice& l : env.levels) {
        if (l.file == env.current_level) return l.name;
    }
    return ascii_upper(env.current_level.stem().string());
}

// One DIP switch: the level's rule, then each setting of the switch, wrapping.
std::optional<int> cycle_dip(std::span<const int> values, const std::optional<int>& current,
                             int by) {
    const auto n = static_cast<int>(values.size()) + 1;  // + the level's own
    int i = 0;
    if (current) {
        const auto it = std::find(values.begin(), values.end(), *current);
        i = it == values.end() ? 0 : static_cast<int>(it - values.begin()) + 1;
    }
    i = ((i + by) % n + n) % n;
    if (i == 0) return std::nullopt;
    return values[static_cast<std::size_t>(i - 1)];
}

std::string dip_label(const std::optional<int>& v) {
    return v ? std::to_string(*v) : std::string("LEVEL'S");
}

std::string scale_label(float s) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%gX", static_cast<double>(s));  // 1X, 1.25X, 2X
    return buf;
}

std::string hint_keys(const platform::Bindings& b, Action a) {
    return platform::keys_label(b, a, 1);
}

}  // namespace

std::string action_label(Action a) {
    switch (a) {
        case Action::left_tread_forward:
            return "LEFT TREAD FORWARD";
        case Action::left_tread_back:
            return "LEFT TREAD BACK";
        case Action::right_tread_forward:
            return "RIGHT TREAD FORWARD";
        case Action::right_tread_back:
            return "RIGHT TREAD BACK";
        case Action::drive_forward:
            return "DRIVE FORWARD";
        case Action::drive_back:
            return "DRIVE BACK";
        case Action::turn_left:
            return "TURN LEFT";
        case Action::turn_right:
            return "TURN RIGHT";
        case Action::fire:
            return "FIRE";
        case Action::pause:
            return "PAUSE";
        case Action::fullscreen:
            return "FULLSCREEN";
        case Action::screenshot:
            return "SCREENSHOT";
        case Action::reload_shaders:
            return "RELOAD SHADERS";
        case Action::mute:
            return "MUTE";
        case Action::volume_up:
            return "VOLUME UP";
        case Action::volume_down:
            return "VOLUME DOWN";
        case Action::quit:
            return "QUIT";
        case Action::start:
            return "START / SELECT";
        case Action::back:
            return "BACK / ERASE";
        case Action::vector_screenshot:
            return "SVG SCREENSHOT";
        default:
            break;
    }
    // Actions added later still get a readable name: their settings-file name.
    return ascii_upper(std::string(platform::action_name(a)));
}

// The pad's controls of an action on the Controls page: its sticks (by the gamepad layout),
// then its buttons as bound ([buttons] in the settings, rebound on the Keys page).
std::string pad_label(Action a, const platform::Settings& st) {
    const bool tank = st.gamepad == platform::GamepadMode::tank;
    std::string sticks;
    switch (a) {
        case Action::left_tread_forward:
        case Action::left_tread_back:
            sticks = tank ? "LEFT STICK" : "";
            break;
        case Action::right_tread_forward:
        case Action::right_tread_back:
            sticks = tank ? "RIGHT STICK" : "";
            break;
        case Action::drive_forward:
        case Action::drive_back:
        case Action::turn_left:
        case Action::turn_right:
            sticks = tank ? "D-PAD (MENUS)" : "LEFT STICK";
            break;
        case Action::fire:
            sticks = "TRIGGERS";
            break;
        default:
            break;
    }
    const std::string buttons = platform::buttons_label(st.buttons, a);
    if (sticks.empty()) return buttons;
    return buttons.empty() ? sticks : buttons + ", " + sticks;
}

PlayMenus::PlayMenus(Env env) : env_(std::move(env)) {}

void PlayMenus::set_context(Context c) {
    if (c == context_) return;
    context_ = c;
    capturing_ = false;
    status_.clear();
    stack_.clear();
    if (c == Context::title) stack_.push_back({Screen::title});
    if (c == Context::paused) stack_.push_back({Screen::paused});
}

void PlayMenus::open_page(Screen s) {
    if (!stack_.empty() && stack_.back().screen == s) return;
    stack_.push_back({s});
    const Page p = page();  // start on the first row that can be chosen
    if (!p.rows.empty() && !p.rows.front().selectable) move(1);
}

std::string PlayMenus::hint(Screen s) const {
    const platform::Bindings& b = env_.settings->keys;
    const std::string choose =
        hint_keys(b, Action::drive_forward) + " / " + hint_keys(b, Action::drive_back) + " CHOOSE";
    const std::string select = hint_keys(b, Action::start) + " SELECT";
    const std::string back = hint_keys(b, Action::back) + " BACK";
    const std::string pad = "   PAD: D-PAD, A, B";
    switch (s) {
        case Screen::title:
            return choose + "   " + select + "   " + hint_keys(b, Action::quit) + " QUIT" + pad;
        case Screen::paused:
            return platform::keys_label(b, Action::pause) + " RESUME   " + choose + "   " + select +
                   pad;
        case Screen::options:
        case Screen::comfort:
        case Screen::arcade:
            return choose + "   " + hint_keys(b, Action::turn_left) + " / " +
                   hint_keys(b, Action::turn_right) + " CHANGE   " + back + pad;
        case Screen::keys:
            return capturing_ ? std::string("PRESS THE NEW KEY OR BUTTON   ESCAPE CANCELS")
                              : choose + "   " + select + " TO REBIND   " + back;
        default:
            return choose + "   " + select + "   " + back + pad;
    }
}

Page PlayMenus::build(Screen s) const {
    const platform::Settings& st = *env_.settings;
    Page p;
    p.hint = hint(s);
    switch (s) {
        case Screen::title:
            p.title = "BEAMZONE";
            p.big_title = true;
            p.rows = {item("START"),       choice("LEVEL", level_label(env_)),
                      item("OPTIONS"),     item("CONTROLS"),
                      item("HIGH SCORES"), item("QUIT")};
            break;
        case Screen::paused:
            p.title = "PAUSED";
            p.under_band = true;
            p.rows = {item("RESUME"), item("OPTIONS"), item("CONTROLS"), item("QUIT TO TITLE")};
            break;
        case Screen::levels:
            p.title = "LEVEL";
            p.columns = true;
            for (const LevelChoice& l : env_.levels) {
                Row r = item(l.name, l.user ? "YOUR LEVEL" : "");
                if (l.file == env_.current_level) r.note = "PLAYING";
                if (!l.loads) {
                    r.note = "HAS ERRORS";
                    r.warn = true;
                }
                p.rows.push_back(r);
            }
            p.rows.push_back(item("BACK"));
            // The selected level's one line (the page is built for the row selected now).
            if (!stack_.empty() && stack_.back().screen == Screen::levels &&
                stack_.back().selected < env_.levels.size()) {
                const std::string& d = env_.levels[stack_.back().selected].description;
                for (std::string& line : two_lines(d)) p.lines.push_back(std::move(line));
            }
            break;
        case Screen::options: {
            p.title = "OPTIONS";
            p.columns = true;
            const int volume = static_cast<int>(std::lround(st.volume * 100.0f));
            const bool tank = st.gamepad == platform::GamepadMode::tank;
            const std::string difficulty =
                st.difficulty == "level" ? std::string("LEVEL'S") : ascii_upper(st.difficulty);
            std::string vsync_note;
            if (env_.vsync_given && *env_.vsync_given != st.vsync) {
                // What the driver gave, not what was asked for.
                vsync_note =
                    "GOT " + ascii_upper(std::string(platform::vsync_name(*env_.vsync_given)));
            }
            p.rows = {
                choice("DIFFICULTY", difficulty, context_ == Context::paused ? "NEXT GAME" : ""),
                choice("PRESET", ascii_upper(st.preset)),
                choice("STYLE", ascii_upper(st.style)),
                choice("BEAM", ascii_upper(st.beam),
                       st.beam == "mame" ? "PHOSPHOR, GLOW" : "STEADY"),
                choice("EFFECTS VOLUME", std::to_string(volume) + "%", st.mute ? "MUTED" : ""),
                choice("FULLSCREEN", on_off(st.fullscreen)),
                choice("VSYNC", ascii_upper(std::string(platform::vsync_name(st.vsync))),
                       vsync_note),
                choice("SHOW FPS", on_off(st.show_fps)),
                choice("FRAME RATE CAP", st.max_fps > 0 ? std::to_string(st.max_fps) : "AUTO",
                       st.max_fps > 0 ? "ALWAYS" : "DISPLAY RATE WITHOUT VSYNC"),
                item("COMFORT AND TEXT"),
                item("ARCADE SETTINGS", st.arcade.any() ? "CHANGED" : ""),
                choice("GAMEPAD LAYOUT", tank ? "TANK" : "DRIVE",
                       tank ? "STICK PER TREAD" : "LEFT STICK"),
                item("KEYS"),
                item("RESET KEYS AND BUTTONS"),
                item("BACK"),
            };
            if (vsync_note.size()) p.rows[o_vsync].warn = true;
            if (!env_.save_status.empty()) p.lines.push_back(env_.save_status);
            break;
        }
        case Screen::comfort: {
            p.title = "COMFORT AND TEXT";
            p.columns = true;
            p.rows = {
                choice("TEXT SIZE", scale_label(st.ui_scale), "MENUS AND HUD"),
                choice("FLICKER AND FLASHES", ascii_upper(st.flashes),
                       st.flashes == "full"   ? "AS DESIGNED"
                       : st.flashes == "soft" ? "HALVED"
                                              : "NO FLICKER, FLASH OR TRAILS"),
                choice("COLOUR-SAFE PALETTE", on_off(st.colour_safe),
                       st.colour_safe ? "RED SHOWN VIOLET-BLUE" : ""),
                item("BACK"),
            };
            if (!env_.save_status.empty()) p.lines.push_back(env_.save_status);
            break;
        }
        case Screen::arcade: {
            p.title = "ARCADE SETTINGS";
            p.columns = true;
            const platform::ArcadeDips& d = st.arcade;
            std::string bonus = "LEVEL'S";
            if (d.bonus_score) {
                bonus = *d.bonus_score == 0 ? std::string("NONE")
                                            : std::to_string(*d.bonus_score) + " AND " +
                                                  std::to_string(platform::kDipSecondBonus);
            }
            p.rows = {
                choice("TANKS", dip_label(d.lives), "2 TO 5"),
                choice("MISSILES FROM", dip_label(d.missile_score), "5000 TO 30000"),
                choice("BONUS TANKS", bonus),
                item("BACK"),
            };
            p.lines.push_back("THE 1980 MACHINE'S SWITCHES. SCORES ARE KEPT APART BY THEM");
            if (context_ == Context::paused) p.lines.push_back("FROM THE NEXT GAME");
            if (!env_.save_status.empty()) p.lines.push_back(env_.save_status);
            break;
        }
        case Screen::keys: {
            p.title = "KEYS";
            p.columns = true;
            for (std::size_t i = 0; i < platform::kActionCount; ++i) {
                const auto a = static_cast<Action>(i);
                Row r = item(action_label(a), platform::keys_label(st.keys, a, 3),
                             platform::buttons_label(st.buttons, a));
                for (const platform::KeyBinding& k : st.keys[i]) {
                    if (const auto other = platform::conflicting_action(st.keys, a, k)) {
                        r.warn = true;
                        r.note = "ALSO " + action_label(*other);
                        break;
                    }
                }
                p.rows.push_back(r);
            }
            p.rows.push_back(item("BACK"));
            if (capturing_) {
                p.lines.push_back("PRESS A KEY OR A PAD BUTTON FOR " +
                                  action_label(static_cast<Action>(selected())));
            } else if (!status_.empty()) {
                p.lines.push_back(status_);
            }
            break;
        }
        case Screen::controls: {
            p.title = "CONTROLS";
            p.columns = true;
            for (std::size_t i = 0; i < platform::kActionCount; ++i) {
                const auto a = static_cast<Action>(i);
                p.rows.push_back(
                    item(action_label(a), platform::keys_label(st.keys, a, 3), pad_label(a, st)));
            }
            p.rows.push_back(item("BACK"));
            break;
        }
        case Screen::confirm_quit: {
            p.title = "QUIT THIS GAME?";
            p.under_band = true;
            p.rows = {item("KEEP PLAYING"),
                      item(env_.score_qualifies ? "QUIT AND ENTER INITIALS" : "QUIT TO TITLE")};
            p.lines.push_back("SCORE " + std::to_string(env_.score_at_stake) +
                              (env_.score_qualifies ? ": A HIGH SCORE, KEPT WITH YOUR INITIALS"
                                                    : ": NOT A HIGH SCORE, IT WILL BE LOST"));
            break;
        }
        case Screen::high_scores: {
            p.title = "HIGH SCORES";
            p.columns = true;
            if (!env_.high_scores_level.empty()) p.rows.push_back(info(env_.high_scores_level, ""));
            if (env_.high_scores) {
                int rank = 1;
                for (const game::HighScore& e : env_.high_scores->entries()) {
                    p.rows.push_back(
                        info(std::to_string(rank++) + ".  " + e.initials, std::to_string(e.score)));
                }
            }
            p.rows.push_back(item("BACK"));
            break;
        }
    }
    return p;
}

Page PlayMenus::page() const {
    if (stack_.empty()) return {};
    return build(stack_.back().screen);
}

void PlayMenus::move(int by) {
    if (stack_.empty()) return;
    const Page p = page();
    if (p.rows.empty()) return;
    const auto n = static_cast<int>(p.rows.size());
    int i = static_cast<int>(stack_.back().selected);
    for (int step = 0; step < n; ++step) {  // skip rows that cannot be chosen
        i = ((i + by) % n + n) % n;
        if (p.rows[static_cast<std::size_t>(i)].selectable) break;
    }
    stack_.back().selected = static_cast<std::size_t>(i);
}

void PlayMenus::back(std::vector<Request>& out) {
    if (stack_.size() > 1) {
        stack_.pop_back();
        status_.clear();
    } else if (context_ == Context::paused) {
        out.push_back({Request::Kind::resume});  // the pause key resumes, as the hint says
    } else if (context_ == Context::title && !stack_.empty()) {
        stack_.back().selected = t_quit;  // one more BACK-then-SELECT to leave, not one key
    }
}

std::vector<Request> PlayMenus::change(int by) {
    std::vector<Request> out;
    platform::Settings& st = *env_.settings;
    const std::size_t row = selected();
    if (screen() == Screen::title && row == t_level) {
        if (env_.levels.empty()) return out;
        std::vector<std::string> files;
        for (const auto& l : env_.levels) files.push_back(l.file.string());
        out.push_back({Request::Kind::choose_level, cycle(files, env_.current_level.string(), by)});
        return out;
    }
    if (screen() == Screen::comfort) {
        switch (row) {
            case c_ui_scale: {
                const float v = std::round((st.ui_scale + static_cast<float>(by) * kUiScaleStep) /
                                           kUiScaleStep) *
                                kUiScaleStep;
                st.ui_scale = v > platform::kMaxUiScale + 1e-3f   ? platform::kMinUiScale
                              : v < platform::kMinUiScale - 1e-3f ? platform::kMaxUiScale
                                                                  : v;
                break;
            }
            case c_flashes:
                st.flashes =
                    cycle({std::begin(platform::kFlashLevels), std::end(platform::kFlashLevels)},
                          st.flashes, by);
                break;
            case c_colour_safe:
                st.colour_safe = !st.colour_safe;
                break;
            default:
                return out;
        }
        out.push_back({Request::Kind::settings_changed});
        return out;
    }
    if (screen() == Screen::arcade) {
        platform::ArcadeDips& d = st.arcade;
        switch (row) {
            case a_lives:
                d.lives = cycle_dip(platform::kDipLives, d.lives, by);
                break;
            case a_missile:
                d.missile_score = cycle_dip(platform::kDipMissileScores, d.missile_score, by);
                break;
            case a_bonus:
                d.bonus_score = cycle_dip(platform::kDipBonusScores, d.bonus_score, by);
                break;
            default:
                return out;
        }
        out.push_back({Request::Kind::settings_changed});
        return out;
    }
    if (screen() != Screen::options) return out;
    switch (row) {
        case o_difficulty:
            st.difficulty =
                cycle({std::begin(kDifficulties), std::end(kDifficulties)}, st.difficulty, by);
            break;
        case o_beam:
            st.beam = cycle({std::begin(kBeams), std::end(kBeams)}, st.beam, by);
            break;
        case o_max_fps: {
            const auto caps = std::span<const int>(kFrameRateCaps);
            const auto it = std::find(caps.begin(), caps.end(), st.max_fps);
            const auto n = static_cast<int>(caps.size());
            const int i = it == caps.end() ? 0 : static_cast<int>(it - caps.begin());
            st.max_fps = caps[static_cast<std::size_t>(((i + by) % n + n) % n)];
            break;
        }
        case o_preset:
            st.preset = cycle(env_.presets, st.preset, by);
            break;
        case o_style:
            // An old name ("occluded") counts as the style it names.
            st.style = cycle(style_names(),
                             std::string(scene::style_name(
                                 scene::style_from_name(st.style).value_or(scene::Style::vector))),
                             by);
            break;
        case o_volume: {
            const float v =
                std::round((st.volume + static_cast<float>(by) * platform::kVolumeStep) /
                           platform::kVolumeStep) *
                platform::kVolumeStep;
            st.volume = v > 1.0f + 1e-3f ? 0.0f : (v < -1e-3f ? 1.0f : std::clamp(v, 0.0f, 1.0f));
            break;
        }
        case o_fullscreen:
            st.fullscreen = !st.fullscreen;
            break;
        case o_vsync: {
            const std::vector<std::string> modes = {"off", "on", "adaptive"};
            platform::parse_vsync(cycle(modes, std::string(platform::vsync_name(st.vsync)), by),
                                  &st.vsync);
            break;
        }
        case o_gamepad:
            st.gamepad = st.gamepad == platform::GamepadMode::tank ? platform::GamepadMode::drive
                                                                   : platform::GamepadMode::tank;
            break;
        case o_fps:
            st.show_fps = !st.show_fps;
            break;
        default:
            return out;
    }
    out.push_back({Request::Kind::settings_changed});
    return out;
}

std::vector<Request> PlayMenus::confirm() {
    std::vector<Request> out;
    const std::size_t row = selected();
    const Page p = page();
    const bool is_back = row < p.rows.size() && p.rows[row].label == "BACK";
    if (is_back) {
        back(out);
        return out;
    }
    switch (screen()) {
        case Screen::title:
            switch (row) {
                case t_start:
                    out.push_back({Request::Kind::start_game});
                    break;
                case t_level:
                    open_page(Screen::levels);
                    break;
                case t_options:
                    open_page(Screen::options);
                    break;
                case t_controls:
                    open_page(Screen::controls);
                    break;
                case t_scores:
                    open_page(Screen::high_scores);
                    break;
                case t_quit:
                    out.push_back({Request::Kind::quit});
                    break;
                default:
                    break;
            }
            break;
        case Screen::paused:
            switch (row) {
                case p_resume:
                    out.push_back({Request::Kind::resume});
                    break;
                case p_options:
                    open_page(Screen::options);
                    break;
                case p_controls:
                    open_page(Screen::controls);
                    break;
                case p_quit_to_title:
                    // A game with a score is never thrown away on one key: ask first.
                    if (env_.score_at_stake > 0) {
                        open_page(Screen::confirm_quit);
                    } else {
                        out.push_back({Request::Kind::quit_to_title});
                    }
                    break;
                default:
                    break;
            }
            break;
        case Screen::levels:
            if (row < env_.levels.size()) {
                out.push_back({Request::Kind::choose_level, env_.levels[row].file});
                stack_.pop_back();
            }
            break;
        case Screen::options:
            if (row == o_keys) {
                open_page(Screen::keys);
            } else if (row == o_comfort) {
                open_page(Screen::comfort);
            } else if (row == o_arcade) {
                open_page(Screen::arcade);
            } else if (row == o_reset_keys) {
                env_.settings->keys = platform::default_bindings();
                env_.settings->buttons = platform::default_pad_bindings();
                out.push_back({Request::Kind::settings_changed});
            } else {
                out = change(1);
            }
            break;
        case Screen::comfort:
        case Screen::arcade:
            out = change(1);
            break;
        case Screen::confirm_quit:
            if (row == 1)
                out.push_back({Request::Kind::quit_to_title});
            else
                back(out);  // KEEP PLAYING: the pause menu again
            break;
        case Screen::keys:
            if (row < platform::kActionCount) {
                capturing_ = true;
                out.push_back({Request::Kind::begin_capture});
            }
            break;
        default:
            break;
    }
    return out;
}

std::vector<Request> PlayMenus::handle(MenuKey key) {
    std::vector<Request> out;
    if (!open() || capturing_) return out;
    switch (key) {
        case MenuKey::up:
            move(-1);
            break;
        case MenuKey::down:
            move(1);
            break;
        case MenuKey::left:
            out = change(-1);
            break;
        case MenuKey::right:
            out = change(1);
            break;
        case MenuKey::confirm:
            out = confirm();
            break;
        case MenuKey::back:
            back(out);
            break;
    }
    return out;
}

std::vector<Request> PlayMenus::pointer(Pointer what, glm::vec2 at, const scene::VectorFont& font,
                                        double aspect) {
    std::vector<Request> out;
    if (!open() || capturing_ || stack_.empty()) return out;
    const float scale = env_.settings ? env_.settings->ui_scale : 1.0f;
    const Page p = page();
    const auto hit = row_at(place(font, p, selected(), aspect, scale), p, at);
    switch (what) {
        case Pointer::move:
            if (hit) stack_.back().selected = *hit;
            break;
        case Pointer::click:
            if (hit) {
                stack_.back().selected = *hit;
                out = confirm();
            }
            break;
        case Pointer::back:
            back(out);
            break;
        case Pointer::wheel_up:
        case Pointer::wheel_down: {
            // The wheel stops at the ends of a list rather than wrapping round.
            const std::size_t before = selected();
            const int by = what == Pointer::wheel_up ? -1 : 1;
            move(by);
            if ((by < 0 && selected() > before) || (by > 0 && selected() < before)) {
                stack_.back().selected = before;
            }
            break;
        }
    }
    return out;
}

std::vector<Request> PlayMenus::captured(const platform::KeyBinding& key) {
    std::vector<Request> out;
    if (!capturing_) return out;
    capturing_ = false;
    const auto action = static_cast<Action>(selected());
    if (key == platform::Input::kCaptureCancelled || selected() >= platform::kActionCount) {
        status_ = "NOT CHANGED";
        return out;
    }
    env_.settings->keys[selected()] = {key};
    status_ = action_label(action) + " IS NOW " + ascii_upper(platform::key_name(key));
    if (const auto other = platform::conflicting_action(env_.settings->keys, action, key)) {
        status_ += " - ALSO BOUND TO " + action_label(*other);
    }
    out.push_back({Request::Kind::settings_changed});
    return out;
}

std::vector<Request> PlayMenus::captured_button(int button) {
    std::vector<Request> out;
    if (!capturing_) return out;
    capturing_ = false;
    if (selected() >= platform::kActionCount) return out;
    const auto action = static_cast<Action>(selected());
    env_.settings->buttons[selected()] = {button};
    status_ = action_label(action) + " IS NOW BUTTON " + platform::button_label(button);
    out.push_back({Request::Kind::settings_changed});
    return out;
}

float PlayMenus::scene_intensity() const {
    if (!open()) return 1.0f;
    switch (screen()) {
        case Screen::title:
            return 0.45f;  // on top of the game's own dimming of the demo
        case Screen::paused:
        case Screen::confirm_quit:
            return 0.6f;
        default:
            return 0.15f;  // lists of text: the scene only as a faint backdrop
    }
}

bool PlayMenus::keeps_game_hud() const {
    return !open() || screen() == Screen::paused || screen() == Screen::title ||
           screen() == Screen::confirm_quit;
}

void PlayMenus::draw(std::vector<scene::HudLine>& out, const scene::VectorFont& font, double aspect,
                     std::uint64_t tick, FooterLine footer) const {
    if (!open() || stack_.empty()) return;
    menu::draw(out, font, page(), selected(), aspect, tick,
               env_.settings ? env_.settings->ui_scale : 1.0f, footer);
}

}  // namespace bz::app::menu
