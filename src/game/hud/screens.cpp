#include "game/hud/screens.h"

#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"

namespace bz::game::screens {

namespace {

using scene::TextAlign;

bool blink(std::uint64_t tick, std::uint64_t period = 40) {
    return (tick / (period / 2)) % 2 == 0;
}

}  // namespace

void title(std::vector<scene::HudLine>& out, const scene::VectorFont* font, double aspect,
           std::uint64_t tick, int high_score, const std::string& hint) {
    hud::text(out, font, "BEAMZONE", {0.0f, 0.42f}, 0.2f, hud::kGreen, TextAlign::center, 1.4f);
    hud::text(out, font, "A VECTOR TANK BATTLE", {0.0f, 0.28f}, 0.05f, hud::kGreen,
              TextAlign::center);
    if (blink(tick, 60)) {
        hud::text(out, font, hint, {0.0f, -0.55f}, 0.07f, hud::kRed, TextAlign::center, 1.2f);
    }
    hud::text(out, font, "HIGH SCORE " + std::to_string(high_score),
              {static_cast<float>(aspect) - hud::kMargin, hud::kTopLine}, hud::kTextHeight,
              hud::kRed, TextAlign::right);
    // A row of tanks under the title, as on the arcade's attract screen.
    for (int i = -2; i <= 2; ++i) {
        hud::tank_icon(out, {0.22f * static_cast<float>(i), -0.3f}, 0.12f, hud::kGreen);
    }
}

void high_scores(std::vector<scene::HudLine>& out, const scene::VectorFont* font,
                 const HighScoreTable& table, int highlight, std::uint64_t tick) {
    hud::text(out, font, "HIGH SCORES", {0.0f, 0.62f}, 0.09f, hud::kRed, TextAlign::center, 1.2f);
    float y = 0.45f;
    int rank = 0;
    for (const HighScore& e : table.entries()) {
        const bool flash = rank == highlight;
        if (!flash || blink(tick)) {
            const float i = flash ? 1.5f : 1.0f;
            hud::text(out, font, std::to_string(rank + 1) + ".", {-0.42f, y}, 0.055f, hud::kGreen,
                      TextAlign::right, i);
            hud::text(out, font, e.initials, {-0.32f, y}, 0.055f, hud::kGreen, TextAlign::left, i);
            hud::text(out, font, std::to_string(e.score), {0.42f, y}, 0.055f, hud::kGreen,
                      TextAlign::right, i);
        }
        y -= 0.1f;
        ++rank;
    }
}

void paused(std::vector<scene::HudLine>& out, const scene::VectorFont* font,
            const std::string& hint) {
    hud::text(out, font, "PAUSED", {0.0f, -0.35f}, 0.12f, hud::kWhite, TextAlign::center, 1.3f);
    hud::text(out, font, hint, {0.0f, -0.5f}, 0.045f, hud::kWhite, TextAlign::center);
}

void game_over(std::vector<scene::HudLine>& out, const scene::VectorFont* font, int score) {
    hud::text(out, font, "GAME OVER", {0.0f, -0.35f}, 0.14f, hud::kRed, TextAlign::center, 1.4f);
    hud::text(out, font, "SCORE " + std::to_string(score), {0.0f, -0.52f}, 0.06f, hud::kRed,
              TextAlign::center);
}

void enter_initials(std::vector<scene::HudLine>& out, const scene::VectorFont* font,
                    const std::string& letters, char current, int score, std::uint64_t tick,
                    const std::string& hint) {
    hud::text(out, font, "GREAT SCORE", {0.0f, 0.55f}, 0.1f, hud::kRed, TextAlign::center, 1.3f);
    hud::text(out, font, std::to_string(score), {0.0f, 0.4f}, 0.07f, hud::kRed, TextAlign::center);
    hud::text(out, font, "ENTER YOUR INITIALS", {0.0f, 0.22f}, 0.06f, hud::kGreen,
              TextAlign::center);
    constexpr float kSlot = 0.18f;
    for (std::size_t i = 0; i < HighScoreTable::kInitials; ++i) {
        const float x = (static_cast<float>(i) - 1.0f) * kSlot;
        char c = ' ';
        if (i < letters.size()) c = letters[i];
        if (i == letters.size()) c = current;
        const bool active = i == letters.size();
        if (!active || blink(tick, 30)) {
            hud::text(out, font, std::string(1, c), {x, -0.05f}, 0.12f, hud::kWhite,
                      TextAlign::center, active ? 1.5f : 1.0f);
        }
        out.push_back({{x - 0.06f, -0.1f}, {x + 0.06f, -0.1f}, hud::kGreen, active ? 1.4f : 0.8f});
    }
    hud::text(out, font, hint, {0.0f, -0.35f}, 0.04f, hud::kGreen, TextAlign::center);
}

void replay_banner(std::vector<scene::HudLine>& out, const scene::VectorFont* font, double aspect,
                   const std::string& note) {
    const float left = -static_cast<float>(aspect) + hud::kMargin;
    hud::text(out, font, note.empty() ? std::string("REPLAY") : "REPLAY  " + note, {left, -0.92f},
              0.04f, hud::kWhite, TextAlign::left, 0.8f);
}

}  // namespace bz::game::screens
