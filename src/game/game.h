#pragma once
// The whole game for the play loop: screens (attract, play, pause, game over, initials, high
// scores), the world in play, its HUD, sounds, high scores, and recording or playing replays.
//
//   game::Game game(level, options, &font);
//   each frame:  for (plan.ticks) game.tick(command_from_input);
//                renderer.render(game.frame(plan.alpha, aspect), game.meshes());
//                synth.play(game.sounds());   // the last tick's
//                if (game.take_highscores_changed()) save the table game.highscores();
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "game/assets/assets.h"
#include "game/difficulty/arcade_rules.h"
#include "game/hud/screens.h"
#include "game/records/highscores.h"
#include "game/records/replay.h"
#include "game/world/events.h"
#include "game/world/tick_command.h"
#include "game/world/world.h"
#include "level/level.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"
#include "scene/vector_font.h"

namespace bz::game {

enum class Screen : std::uint8_t {
    attract,  // title and demo; start begins a game
    playing,
    paused,
    game_over,       // "GAME OVER" for a few seconds
    enter_initials,  // a score made the table
    high_scores,     // the table, then back to attract
};

struct GameOptions {
    std::uint64_t seed = 1;  // the first game's seed; each later game adds one
    int lives = 0;           // 0: the level's [player] lives
    // Empty: the level's [enemies] difficulty (--difficulty and the settings file set it).
    std::optional<level::Difficulty> difficulty;
    ArcadeRules arcade;  // the operator's settings over the level's rules (lives: `lives` wins)
    HighScoreTable highscores = HighScoreTable::defaults();
    // What replays name as the level: empty = the level's file path, or "builtin:default".
    std::string level_name;
    bool record = false;  // record every game (see recording())
    bool attract = true;  // false: start playing at once (tests, benchmarks)
    int hash_interval = 60;
    double fov_y_deg = 45.0;
    // The app draws its own title and pause menus over the game: the attract screen then
    // shows the demo without the title text, pause shows no text, and the app starts, resumes
    // and leaves games through start_game(), resume() and quit_to_title().
    bool app_menus = false;
    screens::Hints hints;
    float text_scale = 1.0f;  // the HUD's status text (hud::View::text_scale)
};

// What reload_level() did.
struct ReloadReport {
    WorldReload world;  // the game in play (all false when there is none)
    // A recording the reload ended: replays belong to one level, so it stops at the edit,
    // with the final state hash of the old level's world. Later games are not recorded.
    std::optional<replay::Replay> ended_recording;
};

class Game {
  public:
    // Throws UserError (file:line:col) when the level names an object kind with no factory
    // or a model that does not load. `font` may be null (no text) and must outlive the game.
    Game(level::Level level, GameOptions options, const scene::VectorFont* font = nullptr);
    ~Game();
    Game(const Game&) = delete;
    Game& operator=(const Game&) = delete;

    // One 60 Hz tick.
    void tick(const TickCommand& command);

    // Takes an edited level into the running game (hot reload): the game in play keeps its
    // score, lives, screen, tank and hostile (see World::reload_level), the attract demo goes
    // on in the new level, new games start in it, and meshes() stays the same library with
    // changed meshes replaced. Throws UserError (file:line:col) with the game unchanged when
    // the level does not build, and during a replay (a replay keeps its level).
    ReloadReport reload_level(const level::Level& level);

    // What to draw, interpolated `alpha` of the way from the previous tick to the last.
    scene::FrameList frame(double alpha, double aspect) const;
    // Whether frame() shows the game's own world (playing, paused, game over), not the demo's:
    // when it switches, the camera cuts to another tank.
    bool shows_live_world() const;
    const scene::MeshLibrary& meshes() const { return assets_->meshes(); }
    // The last tick's sounds.
    const SoundFrame& sounds() const { return sounds_; }

    Screen screen() const { return screen_; }
    // The game in play or just ended; null before the first game.
    const World* world() const { return world_.get(); }
    const level::Level& level() const { return level_; }
    // The difficulty games are played at: the options', else the level's default.
    level::Difficulty difficulty() const;

    const HighScoreTable& highscores() const { return highscores_; }
    // Shows another level's table from now on (high scores are kept per level).
    void set_highscores(HighScoreTable table) { highscores_ = std::move(table); }
    // The level's name as the table screens show it (upper case, printable, bounded).
    std::string highscores_title() const;
    // True once after the table changed: the caller saves it then.
    bool take_highscores_changed();

    // For the app's menus (outside the simulation; a recording begins with the game).
    void start_game();
    void resume();  // paused -> playing
    // Ends the game in play: a score that makes the table is entered first (initials, then
    // the table), as when the game is over; any other goes straight to the title.
    void quit_to_title();
    // Whether the game in play would make the table if it ended now.
    bool score_qualifies() const;
    void set_hints(screens::Hints hints) { options_.hints = std::move(hints); }
    void set_text_scale(float scale) { options_.text_scale = scale; }
    // Difficulty and arcade rules for the games started from now on (the one in play keeps
    // its own); the demo takes them at once.
    void set_rules(std::optional<level::Difficulty> difficulty, const ArcadeRules& arcade);
    const ArcadeRules& arcade_rules() const { return options_.arcade; }

    // Plays a recorded game back from its seed, checking state hashes as it goes. Live input
    // only pauses or quits. Throws UserError if the replay's level hash differs.
    void start_replay(replay::Replay replay);
    bool replaying() const { return playback_.has_value(); }
    bool replay_finished() const { return playback_ && playback_->done(); }
    const std::optional<replay::Mismatch>& replay_mismatch() const { return mismatch_; }

    // The current (or last) game's recording, with its final state hash, or the one a level
    // reload ended; empty when not recording or before the first game.
    std::optional<replay::Replay> recording() const;

  private:
    struct Buttons;
    void end_game();
    void step_world(const TickCommand& command);
    void step_demo();
    void step_initials(const Buttons& b);
    std::string level_name() const;
    // The level as it plays at the chosen difficulty.
    level::Level playing_level(const level::Level& level) const;
    int start_lives() const;
    std::uint64_t level_hash_value() const;

    level::Level level_;
    GameOptions options_;
    const scene::VectorFont* font_;
    std::unique_ptr<Assets> assets_;
    std::unique_ptr<World> world_;
    std::unique_ptr<World> demo_;
    std::optional<replay::Recorder> recorder_;
    std::optional<replay::Replay> ended_recording_;  // see ReloadReport
    std::optional<replay::Player> playback_;
    std::optional<replay::Mismatch> mismatch_;
    mutable std::optional<std::uint64_t> level_hash_;
    HighScoreTable highscores_;
    bool highscores_changed_ = false;
    Screen screen_ = Screen::attract;
    std::uint64_t ticks_ = 0;  // every tick since construction (animations)
    int screen_ticks_ = 0;     // ticks on the current screen
    std::uint64_t games_started_ = 0;
    std::uint64_t demo_games_ = 0;
    std::uint8_t prev_buttons_ = 0;
    int prev_vertical_ = 0;  // -1, 0, 1: treads used as up/down in menus
    std::string initials_;
    char initial_ = 'A';
    int new_rank_ = -1;
    SoundFrame sounds_;
};

}  // namespace bz::game
