#pragma once
// Shared by the tests that render the HUD over a game frame (tests/app/play: the HUD's
// contrast, the filled styles' tiled composite, the menus' haze): a game in play, and each
// pixel's distance to the HUD's strokes.
#include <algorithm>
#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

#include "game/default_level.h"
#include "game/game.h"
#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::test {

// The default level started straight into play (seed 5) and run 90 ticks: the enemy, the
// radar's blips and the score show.
inline std::unique_ptr<game::Game> game_in_play(const scene::VectorFont& font) {
    game::GameOptions options;
    options.seed = 5;
    options.attract = false;
    auto g = std::make_unique<game::Game>(game::default_level(), options, &font);
    for (int i = 0; i < 90; ++i) g->tick(game::TickCommand{});
    return g;
}

// Each pixel's distance (pixel centres, in pixels) to the nearest stroke of `hud` of at least
// `min_intensity`, capped at `cap`, for a w x h frame (HUD units: y up, 1 = half the height).
inline std::vector<float> hud_line_distance(const std::vector<scene::HudLine>& hud, int w, int h,
                                            float cap, float min_intensity = 0.0f) {
    std::vector<float> d(static_cast<std::size_t>(w) * h, cap);
    const float fw = static_cast<float>(w), fh = static_cast<float>(h);
    const auto px = [fw, fh](glm::vec2 u) {
        return glm::vec2(fw * 0.5f + u.x * fh * 0.5f, fh * 0.5f - u.y * fh * 0.5f);
    };
    const int reach = static_cast<int>(cap) + 1;
    for (const scene::HudLine& l : hud) {
        if (l.intensity < min_intensity) continue;
        const glm::vec2 a = px(l.a), b = px(l.b);
        const int x0 = std::max(0, static_cast<int>(std::min(a.x, b.x)) - reach);
        const int x1 = std::min(w - 1, static_cast<int>(std::max(a.x, b.x)) + reach);
        const int y0 = std::max(0, static_cast<int>(std::min(a.y, b.y)) - reach);
        const int y1 = std::min(h - 1, static_cast<int>(std::max(a.y, b.y)) + reach);
        const glm::vec2 ab = b - a;
        const float len2 = std::max(glm::dot(ab, ab), 1e-6f);
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
                const float t = std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f);
                float& v = d[static_cast<std::size_t>(y) * w + x];
                v = std::min(v, glm::length(p - (a + t * ab)));
            }
        }
    }
    return d;
}

}  // namespace bz::test
