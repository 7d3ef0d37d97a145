// Messages, score, high score and reserve tanks along the top of the screen.
#include <algorithm>
#include <cmath>

#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"
#include "game/world/tuning.h"

namespace bz::game::hud {

void text(std::vector<scene::HudLine>& out, const scene::VectorFont* font, std::string_view s,
          glm::vec2 origin, float height, glm::vec3 color, scene::TextAlign align,
          float intensity) {
    if (font == nullptr) return;
    font->draw(out, s, origin, height, color, align, intensity);
}

void tank_icon(std::vector<scene::HudLine>& out, glm::vec2 at, float size, glm::vec3 color) {
    // Side view, facing left: treads, hull, turret and gun.
    const glm::vec2 pts[] = {{-0.45f, 0.0f}, {0.45f, 0.0f},  {0.55f, 0.15f}, {0.5f, 0.3f},
                             {0.25f, 0.3f},  {0.2f, 0.5f},   {-0.15f, 0.5f}, {-0.2f, 0.3f},
                             {-0.5f, 0.3f},  {-0.55f, 0.15f}};
    constexpr std::size_t n = std::size(pts);
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back({at + pts[i] * size, at + pts[(i + 1) % n] * size, color, 1.0f});
    }
    out.push_back(
        {at + glm::vec2(-0.15f, 0.42f) * size, at + glm::vec2(-0.75f, 0.42f) * size, color, 1.0f});
}

void status(std::vector<scene::HudLine>& out, const World& world, const View& view) {
    const auto aspect = static_cast<float>(view.aspect);
    const Awareness a = world.awareness();
    const float left = -aspect + kMargin;
    // The original flashes its warnings; a steady half-second blink keeps it readable.
    const bool blink_on = (world.state().tick / 20) % 3 != 0;
    if (a.enemy_in_range && blink_on) {
        text(out, view.font, "ENEMY IN RANGE", {left, kTopLine}, kTextHeight, kRed);
    }
    if (a.motion_blocked) {
        text(out, view.font, "MOTION BLOCKED BY OBJECT", {left, kSecondLine}, kTextHeight, kRed);
    } else if (a.enemy_present && blink_on) {
        const char* where = nullptr;
        switch (a.direction) {
            case EnemyDirection::left:
                where = "ENEMY TO LEFT";
                break;
            case EnemyDirection::right:
                where = "ENEMY TO RIGHT";
                break;
            case EnemyDirection::rear:
                where = "ENEMY TO REAR";
                break;
            case EnemyDirection::ahead:
            case EnemyDirection::none:
                break;
        }
        if (where) text(out, view.font, where, {left, kSecondLine}, kTextHeight, kRed);
    }

    const float right = aspect - kMargin;
    text(out, view.font, "SCORE " + std::to_string(world.score()), {right, kTopLine}, kTextHeight,
         kRed, scene::TextAlign::right);
    const int high = std::max(view.high_score, world.score());
    text(out, view.font, "HIGH SCORE " + std::to_string(high), {right, kSecondLine}, kTextHeight,
         kRed, scene::TextAlign::right);
    // Reserve tanks: the ones after the tank in play.
    constexpr float kIcon = 0.07f;
    const int reserve = std::max(0, world.lives() - (world.phase() == Phase::game_over ? 0 : 1));
    for (int i = 0; i < reserve; ++i) {
        tank_icon(out, {right - kIcon * 0.6f - static_cast<float>(i) * kIcon * 1.4f, kLivesLine},
                  kIcon, kRed);
    }
}

void play_hud(std::vector<scene::HudLine>& out, const World& world, const View& view) {
    status(out, world, view);
    if (world.phase() == Phase::playing) {
        radar(out, world, view);
        reticle(out, world.awareness().in_sights);
    } else if (world.phase() == Phase::dying) {
        radar(out, world, view);
        const double seconds = (tuning::kDyingTicks - world.state().phase_ticks + view.alpha) /
                               tuning::kTicksPerSecond;
        cracks(out, world.state().crack_seed, seconds, view.aspect);
    }
}

}  // namespace bz::game::hud
