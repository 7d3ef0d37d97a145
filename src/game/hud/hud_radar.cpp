// The radar: a circle at the top of the screen, the player at its centre facing up, a sweep
// turning clockwise, the field of view marked, the hostile as a blip that flares as the sweep
// passes and fades after. The saucer never shows.
#include <cmath>

#include "core/angles.h"
#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"

namespace bz::game::hud {

namespace {

glm::vec2 polar(double clockwise_from_up, float r) {
    return kRadarCenter + r * glm::vec2(static_cast<float>(std::sin(clockwise_from_up)),
                                        static_cast<float>(std::cos(clockwise_from_up)));
}

void line(std::vector<scene::HudLine>& out, glm::vec2 a, glm::vec2 b, float intensity) {
    out.push_back({a, b, kRed, intensity});
}

}  // namespace

void radar(std::vector<scene::HudLine>& out, const World& world, const View& view) {
    constexpr int kSegments = 40;
    for (int i = 0; i < kSegments; ++i) {
        line(out, polar(2.0 * kPi * i / kSegments, kRadarRadius),
             polar(2.0 * kPi * (i + 1) / kSegments, kRadarRadius), 0.7f);
    }
    // Field of view: the camera's horizontal half-angle either side of straight up.
    const double half_fov =
        std::atan(std::tan(view.fov_y_deg * kPi / 360.0) * std::max(0.1, view.aspect));
    line(out, polar(-half_fov, 0.02f), polar(-half_fov, kRadarRadius * 0.45f), 0.6f);
    line(out, polar(half_fov, 0.02f), polar(half_fov, kRadarRadius * 0.45f), 0.6f);
    line(out, kRadarCenter + glm::vec2(-0.008f, 0.0f), kRadarCenter + glm::vec2(0.008f, 0.0f),
         0.8f);

    // The sweep with a short fading trail.
    const double sweep = world.radar_sweep(view.alpha);
    for (int k = 0; k < 4; ++k) {
        const double a = sweep - k * 0.07;
        line(out, kRadarCenter, polar(a, kRadarRadius), 1.0f - 0.24f * static_cast<float>(k));
    }

    const double range = world.radar_range();
    for (const RadarBlip& b : world.radar_blips()) {
        const double bearing = std::atan2(b.offset.x, b.offset.y);
        // How long ago (as a fraction of a turn) the sweep passed it: bright just after.
        const double since = std::fmod(sweep - bearing + 4.0 * kPi, 2.0 * kPi) / (2.0 * kPi);
        const auto intensity = static_cast<float>(0.25 + 1.5 * (1.0 - since));
        const glm::vec2 c = kRadarCenter + glm::vec2(b.offset / range) * kRadarRadius;
        constexpr float s = 0.012f;
        line(out, c + glm::vec2(-s, 0), c + glm::vec2(0, s), intensity);
        line(out, c + glm::vec2(0, s), c + glm::vec2(s, 0), intensity);
        line(out, c + glm::vec2(s, 0), c + glm::vec2(0, -s), intensity);
        line(out, c + glm::vec2(0, -s), c + glm::vec2(-s, 0), intensity);
    }
}

}  // namespace bz::game::hud
