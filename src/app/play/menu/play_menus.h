#pragma once
// The menus around the game, outside the simulation: the title menu (start, level, options,
// controls, high scores, quit), the pause menu (resume, options, controls, quit to title), the
// options (difficulty, preset, style, beam, volume, window, vsync, frame-rate readout; comfort
// and text: text size, flicker and flashes, colour-safe palette; the arcade machine's
// switches; gamepad layout, keys) and
// the controls screen with the keys and buttons actually bound. Driven by menu keys, so the
// keyboard and a gamepad work alike; what a choice does outside the menus (start a game, apply
// and save a setting, capture a key) comes back as requests for the play loop.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/play/menu/menu_page.h"
#include "game/records/highscores.h"
#include "platform/input.h"
#include "platform/settings.h"

namespace bz::app::menu {

enum class Context : std::uint8_t { none, title, paused };

struct LevelChoice {
    std::string name;  // shown, e.g. "NIGHT VOLCANO" (the level's own name)
    std::filesystem::path file;
    bool user = false;        // from the player's own level folder
    std::string description;  // its one line, shown under the list while it is selected
    bool listed = true;       // the level's `listed` key
    bool loads = true;        // false: the file has errors (choosing it shows them)
};

struct Request {
    enum class Kind : std::uint8_t {
        start_game,
        resume,
        quit_to_title,
        quit,
        choose_level,      // `level`
        settings_changed,  // the settings were edited: apply them and save
        begin_capture,     // the next key press is for the keys page (Input::begin_capture)
    };
    Request(Kind k, std::filesystem::path file = {}) : kind(k), level(std::move(file)) {}
    Kind kind;
    std::filesystem::path level;
    bool operator==(const Request&) const = default;
};

// What the menus show and edit; the play loop keeps it up to date.
struct Env {
    platform::Settings* settings = nullptr;  // edited in place
    std::vector<std::string> presets;        // the renderer's preset names
    std::vector<LevelChoice> levels;
    std::filesystem::path current_level;  // empty: the built-in level
    const game::HighScoreTable* high_scores = nullptr;
    std::string high_scores_level;  // whose table that is (kept per level)
    std::string save_status;        // shown on the options page ("SAVED", why not)
    // The game in play under the pause menu: its score (0: nothing to lose) and whether it
    // would make the high-score table (then quitting asks for initials first).
    int score_at_stake = 0;
    bool score_qualifies = false;
    // The vsync the driver gave when it differs from the setting (shown beside it).
    std::optional<platform::Vsync> vsync_given;
};

class PlayMenus {
  public:
    explicit PlayMenus(Env env);

    // What the game shows now: the title menu opens on the attract screen, the pause menu
    // while paused. A change of context starts again at that context's first page.
    void set_context(Context c);
    Context context() const { return context_; }
    bool open() const { return context_ != Context::none; }

    std::vector<Request> handle(platform::MenuKey key);
    // The mouse, at `at` in HUD units (menu_page.h): hovering a row selects it, a click
    // chooses it, the wheel steps through a long list, and the right button goes back.
    enum class Pointer : std::uint8_t { move, click, back, wheel_up, wheel_down };
    std::vector<Request> pointer(Pointer what, glm::vec2 at, const scene::VectorFont& font,
                                 double aspect);
    // The key pressed after a begin_capture request (Input::kCaptureCancelled: none).
    std::vector<Request> captured(const platform::KeyBinding& key);
    // The gamepad button pressed after a begin_capture request: bound to the selected action.
    std::vector<Request> captured_button(int button);
    bool capturing() const { return capturing_; }

    Page page() const;  // the page shown now, as data
    std::size_t selected() const { return stack_.empty() ? 0 : stack_.back().selected; }
    void draw(std::vector<scene::HudLine>& out, const scene::VectorFont& font, double aspect,
              std::uint64_t tick, FooterLine footer = FooterLine::hints) const;

    Env& env() { return env_; }

    // How the game shows under the menu: its scene dimmed by `scene_intensity`, and its HUD
    // kept only under the first page of the pause menu (the score stays in view there).
    float scene_intensity() const;
    bool keeps_game_hud() const;

    enum class Screen : std::uint8_t {
        title,
        levels,
        options,
        comfort,  // text size, flicker and flashes, colour-safe palette
        arcade,   // the arcade machine's DIP switches
        keys,
        controls,
        high_scores,
        paused,
        confirm_quit,  // "QUIT THIS GAME?" when the game in play has a score
    };
    Screen screen() const { return stack_.empty() ? Screen::title : stack_.back().screen; }
    // Opens a page directly, as if chosen from the context's first page (screenshots, tests).
    void open_page(Screen s);

  private:
    struct Open {
        Screen screen;
        std::size_t selected = 0;
    };
    Page build(Screen s) const;
    std::vector<Request> confirm();
    std::vector<Request> change(int by);  // LEFT / RIGHT on a choice row
    void back(std::vector<Request>& out);
    void move(int by);
    std::string hint(Screen s) const;

    Env env_;
    Context context_ = Context::none;
    std::vector<Open> stack_;
    bool capturing_ = false;
    std::string status_;  // one line under the page (the last rebinding)
};

// Human names for actions and gamepad buttons, as the controls screen shows them.
std::string action_label(platform::Action a);
std::string pad_label(platform::Action a, const platform::Settings& settings);

}  // namespace bz::app::menu
