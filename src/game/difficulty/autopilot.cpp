#include "game/difficulty/autopilot.h"

#include <algorithm>
#include <cmath>

namespace bz::game {

TickCommand autopilot(const World& world) {
    const WorldState& s = world.state();
    TickCommand c;
    if (s.phase != Phase::playing) return c;
    const scene::Entity* target = nullptr;
    if (s.hostile) target = &s.hostile->body;
    if (!target && s.saucer) target = &s.saucer->body;
    if (!target) {
        // Nothing to shoot: creep forward in a wide circle, scanning.
        c.left_tread = 0.6f;
        c.right_tread = 0.3f;
        return c;
    }
    const scene::Transform& me = s.player.body.transform;
    const glm::dvec2 d =
        world.field().delta(ground(me.position), ground(target->transform.position));
    const glm::dvec3 f = me.forward();
    const double ahead = d.x * f.x + d.y * f.z;
    const double right = d.x * -f.z + d.y * f.x;  // the right vector is (-f.z, f.x)
    const double bearing = std::atan2(right, ahead);
    // Pivot towards it, gentler when nearly lined up.
    const auto turn = static_cast<float>(std::clamp(bearing * 4.0, -1.0, 1.0));
    c.left_tread = turn;
    c.right_tread = -turn;
    const double dist = glm::length(d);
    const double half_width = target->collider.radius * 0.6;
    const bool lined_up = ahead > 0.0 && std::abs(right) < half_width && dist < 100.0;
    // Press and release on alternate ticks: fire triggers on the press.
    c.fire = lined_up && (s.tick % 2 == 0);
    return c;
}

}  // namespace bz::game
