#pragma once
// Where the HUD puts things, in HUD units (origin at the screen centre, y up, 1 = half the
// screen height, x spans -aspect..aspect). Tests check the drawn lines against these regions.
#include <glm/glm.hpp>

namespace bz::game::hud {

inline constexpr glm::vec2 kRadarCenter{0.0f, 0.74f};
inline constexpr float kRadarRadius = 0.2f;
inline constexpr float kReticleHalfWidth = 0.12f;
inline constexpr float kReticleHalfHeight = 0.2f;
inline constexpr float kTextHeight = 0.045f;
inline constexpr float kMargin = 0.06f;
inline constexpr float kTopLine = 0.88f;     // baseline of the first status line
inline constexpr float kSecondLine = 0.79f;  // baseline of the second
inline constexpr float kLivesLine = 0.68f;   // bottom of the reserve-tank icons

// The arcade's colour overlay: the top strip (radar, messages, score) red, the rest green.
inline constexpr glm::vec3 kRed{1.0f, 0.22f, 0.15f};
inline constexpr glm::vec3 kGreen{0.2f, 1.0f, 0.3f};
inline constexpr glm::vec3 kWhite{0.85f, 1.0f, 0.9f};

}  // namespace bz::game::hud
