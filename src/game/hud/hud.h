#pragma once
// The HUD as lines: radar with its sweep, reticle, messages, score and reserve tanks, and the
// cracked screen when the tank is hit. Text needs a font; without one only the text is left out.
#include <string_view>
#include <vector>

#include "game/world/world.h"
#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::game::hud {

struct View {
    double alpha = 1.0;  // interpolation between the last two ticks
    double aspect = 16.0 / 9.0;
    double fov_y_deg = 45.0;
    int high_score = 0;
    const scene::VectorFont* font = nullptr;
    // The player's text size (1 to 2): status text grows with it as far as its region allows
    // (hud_layout.h), never into its neighbours.
    float text_scale = 1.0f;
};

// The status text height for `view`: kTextHeight scaled, at most what keeps the two status
// lines apart.
float status_text_height(const View& view);

// Text through the font if there is one.
void text(std::vector<scene::HudLine>& out, const scene::VectorFont* font, std::string_view s,
          glm::vec2 origin, float height, glm::vec3 color,
          scene::TextAlign align = scene::TextAlign::left, float intensity = 1.0f);

void radar(std::vector<scene::HudLine>& out, const World& world, const View& view);
void reticle(std::vector<scene::HudLine>& out, bool in_sights);
// "ENEMY IN RANGE", "ENEMY TO LEFT" ..., "MOTION BLOCKED BY OBJECT"; score, high score, tanks.
void status(std::vector<scene::HudLine>& out, const World& world, const View& view);
// Cracks spreading from the hit; `seconds` since the hit (they grow for the first moment).
void cracks(std::vector<scene::HudLine>& out, std::uint32_t seed, double seconds, double aspect);
// A small tank outline for the reserve-tank row, base centred on `at`.
void tank_icon(std::vector<scene::HudLine>& out, glm::vec2 at, float size, glm::vec3 color);

// Everything above for a world in play.
void play_hud(std::vector<scene::HudLine>& out, const World& world, const View& view);

}  // namespace bz::game::hud
