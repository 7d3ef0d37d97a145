// The gunsight: two bracket bars above and below the centre with a post each. When a target
// is lined up and in range, the posts open into a V and the bar ends turn inward.
#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"

namespace bz::game::hud {

void reticle(std::vector<scene::HudLine>& out, bool in_sights) {
    const glm::vec3 c = kGreen;
    const float i = in_sights ? 1.6f : 1.0f;
    constexpr float w = 0.09f;    // bar half width
    constexpr float bar = 0.1f;   // bar height above/below the centre
    constexpr float tip = 0.03f;  // end ticks
    constexpr float post = 0.17f;
    for (const float s : {1.0f, -1.0f}) {  // top, then bottom (mirrored)
        out.push_back({{-w, s * bar}, {w, s * bar}, c, i});
        if (in_sights) {
            out.push_back({{-w, s * bar}, {-w + tip, s * (bar - tip)}, c, i});
            out.push_back({{w, s * bar}, {w - tip, s * (bar - tip)}, c, i});
            out.push_back({{0.0f, s * bar}, {-0.035f, s * post}, c, i});
            out.push_back({{0.0f, s * bar}, {0.035f, s * post}, c, i});
        } else {
            out.push_back({{-w, s * bar}, {-w, s * (bar - tip)}, c, i});
            out.push_back({{w, s * bar}, {w, s * (bar - tip)}, c, i});
            out.push_back({{0.0f, s * bar}, {0.0f, s * post}, c, i});
        }
    }
}

}  // namespace bz::game::hud
