#pragma once
// What the play loop drives: the game itself, or the --edit viewer. The loop owns the window,
// input, timing, audio, hot reload and overlays; a session owns what is simulated and drawn.
#include <string>
#include <vector>

#include "app/play/menu/play_menus.h"
#include "core/interrupt.h"
#include "game/difficulty/arcade_rules.h"
#include "game/records/highscores.h"
#include "level/level.h"
#include "platform/free_fly.h"
#include "platform/input.h"
#include "platform/synth.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::app {

struct SoundCue {
    platform::Sound sound = platform::Sound::radar_blip;
    float gain = 1.0f;
};

struct SessionSounds {
    bool engine_on = false;
    float engine_speed = 0.0f;
    std::vector<SoundCue> events;
};

class PlaySession {
  public:
    virtual ~PlaySession() = default;
    // One fixed 60 Hz step.
    virtual void tick(const platform::InputState& input) = 0;
    // Once per frame with the real frame time (the free-fly camera moves per frame).
    virtual void update(const platform::FlyControls& fly, double dt) = 0;
    // alpha: 0..1 between the previous and the current tick; aspect: width / height.
    virtual scene::FrameList frame(double alpha, double aspect) = 0;
    virtual const scene::MeshLibrary& meshes() const = 0;
    // Whether the picture may keep a past (phosphor trails, a held frame): false for a viewer
    // whose camera flies and jumps (RenderSettings::keep_history).
    virtual bool keeps_history() const { return true; }
    // Sounds of the ticks since the last call.
    virtual SessionSounds take_sounds() = 0;
    // A hot reload produced a new good level: take it in, keeping what is running. meshes()
    // must stay the same library (replacing meshes in it is fine). Throws UserError, with the
    // session unchanged, when the level cannot be used.
    virtual void level_changed(const level::Level& level) = 0;
    // Game actions the player pressed (pause, start, back); window-level ones stay in the loop.
    virtual void on_action(platform::Action) {}
    // Which of the app's menus the session's screen calls for (title, pause, or none).
    virtual menu::Context menu_context() const { return menu::Context::none; }
    // What the menus chose; outside the simulation (a recording starts with the game).
    enum class MenuCommand : std::uint8_t { start_game, resume, quit_to_title };
    virtual void menu_command(MenuCommand) {}
    // The player chose another difficulty ("easy", "normal", "arcade"; "" the level's) or
    // arcade settings: games started from now on play by them.
    virtual void rules_changed(const std::string& /*difficulty*/, const game::ArcadeRules&) {}
    // The player's text size (1 to 2) for the HUD.
    virtual void set_text_scale(float) {}
    // The top of this screen's footer in HUD units (after its last frame): the overlay's
    // readout and notices stack above it.
    virtual float footer_top() const { return -0.88f; }  // game::hud::kFooterTop
    // The player rebound keys: on-screen hints should name the new ones.
    virtual void keys_changed(const platform::Bindings&) {}
    // The score of the game in play (0: none, or nothing to lose) and whether it would make
    // the table: quitting such a game asks first.
    virtual int score_at_stake() const { return 0; }
    virtual bool score_qualifies() const { return false; }
    // The table the High scores page shows; null when the session keeps none.
    virtual const game::HighScoreTable* high_scores() const { return nullptr; }
    // The level that table belongs to (tables are kept per level), as the screen shows it.
    virtual std::string high_scores_level() const { return {}; }
    // The window lost focus (the game pauses itself if the settings say so).
    virtual void on_focus_lost() {}
    // True when the session has nothing more to show (a replay reached its end), or the
    // process was asked to stop (SIGINT, SIGTERM): the loop then ends and play saves.
    virtual bool finished() const { return interrupt_requested(); }
    // True when the run failed in a way the exit code should show (a replay that diverged).
    virtual bool failed() const { return false; }
    // Called once when the run ends, however it ends (quit, --frames, a signal): saves what
    // must outlive it (a recording). False when a save failed (it was reported; the exit code
    // shows it too).
    virtual bool save_on_exit() { return true; }
    // Messages for the player that arose outside the loop (a damaged high-score file), to
    // show on screen once.
    virtual std::vector<std::string> take_notices() { return {}; }
};

}  // namespace bz::app
