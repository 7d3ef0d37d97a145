#pragma once
// The two things `beamzone play` can run: the game, and the --edit level viewer.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "app/play/play_session.h"
#include "game/hud/screens.h"
#include "game/world/events.h"
#include "platform/bindings.h"
#include "platform/settings.h"
#include "scene/vector_font.h"

namespace bz {
class Log;
}

namespace bz::app {

struct SessionOptions {
    const level::Level* level = nullptr;  // nullptr: the game's built-in level
    std::optional<std::uint64_t> seed;    // none: from the clock
    std::string difficulty;               // "easy", "normal", "arcade"; else the level's
    game::ArcadeRules arcade;             // the operator settings (settings file, [arcade])
    std::string record;                   // replay file to write at exit, or empty
    std::string replay;                   // replay file to play back, or empty
    std::filesystem::path high_scores;
    bool pause_on_focus_loss = true;
    const scene::VectorFont* font = nullptr;  // must outlive the session
    bool app_menus = true;  // title and pause menus come from the play loop (game::GameOptions)
    game::screens::Hints hints;  // key hints naming the player's keys
};

// The settings file's DIP switches as the game's rules.
game::ArcadeRules arcade_rules(const platform::ArcadeDips& dips);

// The game's on-screen hints for `keys` ("P / ESCAPE RESUME").
game::screens::Hints screen_hints(const platform::Bindings& keys);

// Throws UserError for a level the game cannot build or an unreadable replay.
std::unique_ptr<PlaySession> make_game_session(const SessionOptions& options, Log& log);
std::unique_ptr<PlaySession> make_edit_session(const SessionOptions& options, Log& log);

// How each game event sounds: which synth voice, how loud.
SoundCue sound_cue(game::SoundEvent e);

}  // namespace bz::app
