#include "app/play/frame_comfort.h"

#include <algorithm>

namespace bz::app {

namespace {

constexpr float kSoftOverdrive = 1.0f / 3.0f;
// How much redder than green a colour must be to count as "red" (the HUD's red is 4.5x).
constexpr float kRedOverGreen = 1.15f;

}  // namespace

float limit_flash(float intensity, std::string_view flashes) {
    if (intensity <= 1.0f || flashes == "full") return intensity;
    if (flashes == "soft") return 1.0f + (intensity - 1.0f) * kSoftOverdrive;
    return 1.0f;
}

glm::vec3 colour_safe(glm::vec3 c) {
    if (c.r <= c.g * kRedOverGreen) return c;
    // Red's energy moves into blue, a little stays in red: violet-blue, which deuteranopes
    // and protanopes see as blue against the green's yellow.
    return {0.6f * c.r, c.g, std::max(c.b, c.r)};
}

void apply_comfort(scene::FrameList& frame, std::string_view flashes, bool colour_safe_palette) {
    const bool limit = flashes != "full";
    if (!limit && !colour_safe_palette) return;
    for (scene::DrawItem& item : frame.items) {
        if (limit) item.intensity = limit_flash(item.intensity, flashes);
        if (colour_safe_palette) item.color = colour_safe(item.color);
    }
    for (scene::HudLine& line : frame.hud) {
        if (limit) line.intensity = limit_flash(line.intensity, flashes);
        if (colour_safe_palette) line.color = colour_safe(line.color);
    }
}

}  // namespace bz::app
