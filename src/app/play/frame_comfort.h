#pragma once
// The player's comfort settings applied to a finished frame, before it is drawn:
//   flashes "soft" / "off": the overdriven flashes (a hit's debris, the cracked screen's rim,
//     a new high score) are toned down or held at full brightness, never above it;
//   colour-safe: red-dominant colours become violet-blue, which stays apart from the game's
//     green for deuteranopes and protanopes (red and green collapse to one hue for them).
// The beam's own flicker and phosphor trails are the look's (play_look.h), not this.
#include <glm/glm.hpp>
#include <string_view>

#include "scene/frame_list.h"

namespace bz::app {

// Intensity as the flash level allows: "full" unchanged, "soft" a third of the overdrive
// above 1 kept, "off" capped at 1.
float limit_flash(float intensity, std::string_view flashes);

// Red-dominant colours as violet-blue, the rest unchanged.
glm::vec3 colour_safe(glm::vec3 c);

void apply_comfort(scene::FrameList& frame, std::string_view flashes, bool colour_safe_palette);

}  // namespace bz::app
