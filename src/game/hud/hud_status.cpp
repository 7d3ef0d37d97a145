// Messages, score, high score and reserve tanks along the top of the screen.
#include <algorithm>
#include <cmath>
#include <string>

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

float status_text_height(const View& view) {
    // The first line's top must stay under the screen's top margin, the second's under the
    // first line's baseline.
    const float most = std::min(kTopLine - kSecondLine, 1.0f - kTopLine - 0.04f);
    return std::clamp(kTextHeight * view.text_scale, kTextHeight, std::max(kTextHeight, most));
}

void status(std::vector<scene::HudLine>& out, const World& world, const View& view) {
    const auto aspect = static_cast<float>(view.aspect);
    const Awareness a = world.awareness();
    const float left = -aspect + kMargin;
    const float h = status_text_height(view);
    // Text that would run past its region at this size is drawn smaller to fit it.
    auto fitted = [&](const std::string& s, const Box& box) {
        if (!view.font) return h;
        const float w = view.font->width(s, h);
        return w > box.width() ? h * box.width() / w : h;
    };
    const Box messages = messages_box(aspect);
    const Box score = score_box(aspect);
    auto message = [&](const std::string& s, float y) {
        text(out, view.font, s, {left, y}, fitted(s, messages), kRed);
    };
    // The original flashes its warnings; a steady half-second blink keeps it readable.
    const bool blink_on = (world.state().tick / 20) % 3 != 0;
    if (a.enemy_in_range && blink_on) {
        message("ENEMY IN RANGE", kTopLine);
    }
    if (a.motion_blocked) {
        message("MOTION BLOCKED BY OBJECT", kSecondLine);
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
        if (where) message(where, kSecondLine);
    }

    const float right = aspect - kMargin;
    const std::string score_text = "SCORE " + std::to_string(world.score());
    const int high = std::max(view.high_score, world.score());
    const std::string high_text = "HIGH SCORE " + std::to_string(high);
    // Both lines at one size: the longer decides.
    const float sh = std::min(fitted(score_text, score), fitted(high_text, score));
    text(out, view.font, score_text, {right, kTopLine}, sh, kRed, scene::TextAlign::right);
    text(out, view.font, high_text, {right, kSecondLine}, sh, kRed, scene::TextAlign::right);
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
