#pragma once
// The screens around play, as HUD lines: title (attract), pause, game over, the high-score
// table and initials entry.
#include <cstdint>
#include <string>
#include <vector>

#include "game/records/highscores.h"
#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::game::screens {

// Key hints naming the player's real keys; the app fills them in from the bindings (the game
// does not know keys). The defaults name the default keyboard keys.
struct Hints {
    std::string initials = "UP / DOWN CHOOSE   SPACE NEXT   BACKSPACE ERASE";
    std::string paused = "P / ESCAPE RESUME   BACKSPACE QUIT";
    std::string title = "RETURN START";
};

void title(std::vector<scene::HudLine>& out, const scene::VectorFont* font, double aspect,
           std::uint64_t tick, int high_score, const std::string& hint);
// `highlight` = rank to flash (a new entry), or -1.
void high_scores(std::vector<scene::HudLine>& out, const scene::VectorFont* font,
                 const HighScoreTable& table, int highlight, std::uint64_t tick);
void paused(std::vector<scene::HudLine>& out, const scene::VectorFont* font,
            const std::string& hint);
void game_over(std::vector<scene::HudLine>& out, const scene::VectorFont* font, int score);
// `letters` so far (cursor at letters.size()), `current` the letter being chosen.
void enter_initials(std::vector<scene::HudLine>& out, const scene::VectorFont* font,
                    const std::string& letters, char current, int score, std::uint64_t tick,
                    const std::string& hint);
void replay_banner(std::vector<scene::HudLine>& out, const scene::VectorFont* font, double aspect,
                   const std::string& note);

}  // namespace bz::game::screens
