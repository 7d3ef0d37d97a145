// The player's tank: tread drive, obstacles that block it, and the gun.
#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "game/world/tuning.h"
#include "game/world/world.h"

namespace bz::game {

glm::dvec2 World::view_to_world(glm::dvec2 view_offset) const {
    const double yaw = cur_.player.body.transform.yaw;
    const glm::dvec2 fwd{-std::sin(yaw), -std::cos(yaw)};
    const glm::dvec2 right{std::cos(yaw), -std::sin(yaw)};
    return player_ground() + right * view_offset.x + fwd * view_offset.y;
}

bool World::blocked(glm::dvec2 p, double radius, bool for_player) const {
    if (!field_.contains(p, radius)) return true;
    if (obstacle_at(p, radius) != nullptr) return true;
    if (cur_.hostile && cur_.hostile->kind != HostileKind::missile) {
        const scene::Entity& other = for_player ? cur_.hostile->body : cur_.player.body;
        const double gap = field_.distance(ground(other.transform.position), p);
        if (gap < radius + other.collider.radius) return true;
    }
    return false;
}

void World::step_player(const PackedCommand& cmd) {
    PlayerTank& p = cur_.player;
    scene::Transform& t = p.body.transform;
    const double left = cmd.left / 127.0;
    const double right = cmd.right / 127.0;
    // Two treads: together they drive, against each other they pivot. The right tread pushing
    // harder swings the tank to the left (positive yaw).
    p.speed = (left + right) * 0.5 * tuning::kPlayerSpeed;
    p.turn_rate = (right - left) * 0.5 * tuning::kPlayerTurnDeg * kPi / 180.0;
    t.yaw = wrap_angle(t.yaw + p.turn_rate * tuning::kDt);

    const glm::dvec3 fwd = t.forward();
    const glm::dvec2 from = player_ground();
    const glm::dvec2 to = from + glm::dvec2(fwd.x, fwd.z) * (p.speed * tuning::kDt);
    if (p.speed != 0.0) {
        if (blocked(to, tuning::kPlayerRadius, true)) {
            if (cur_.blocked_ticks == 0) events_.push_back(SoundEvent::blocked);
            cur_.blocked_ticks = tuning::kBlockedMessageTicks;
            p.speed = 0.0;
        } else {
            const glm::dvec2 w = field_.wrap(to);
            t.position.x = w.x;
            t.position.z = w.y;
        }
    }

    const bool fire = (cmd.buttons & button::fire) != 0;
    if (fire && !p.fire_held) {
        const bool in_flight = std::any_of(cur_.shells.begin(), cur_.shells.end(),
                                           [](const Shell& s) { return s.from_player; });
        if (!in_flight) {
            fire_shell(p.body, true, tuning::kShellSpeed, tuning::kShellRange);
            if (cur_.hostile) cur_.hostile->provoked = true;
            events_.push_back(SoundEvent::shot);
        }
    }
    p.fire_held = fire;
}

void World::fire_shell(const scene::Entity& from, bool from_player, double speed, double range,
                       double yaw_offset) {
    const scene::Transform& t = from.transform;
    const glm::dvec3 fwd = t.forward();
    // Straight along the gun unless told otherwise (bit for bit the gun's own direction).
    const double yaw = yaw_offset == 0.0 ? t.yaw : wrap_angle(t.yaw + yaw_offset);
    const glm::dvec2 dir =
        yaw_offset == 0.0 ? glm::dvec2(fwd.x, fwd.z) : glm::dvec2(-std::sin(yaw), -std::cos(yaw));
    Shell s;
    s.id = cur_.next_id++;
    s.from_player = from_player;
    s.body.behaviour = scene::Behaviour::shell;
    s.body.mesh = models_.shell;
    s.body.color = from_player ? glm::vec3(0.5f, 1.0f, 0.6f) : glm::vec3(1.0f, 0.5f, 0.3f);
    s.body.collider = {scene::ColliderShape::circle, tuning::kShellRadius, {}, 0.6};
    glm::dvec2 start =
        field_.wrap(ground(t.position) + glm::dvec2(fwd.x, fwd.z) * tuning::kMuzzleOffset);
    // Pressed against a wall the muzzle is inside it: start at the tank so the shell's first
    // step meets the wall instead of appearing beyond it.
    if (obstacle_at(start, tuning::kShellRadius, tuning::kShellHeight) != nullptr) {
        start = ground(t.position);
    }
    s.body.transform.position = {start.x, tuning::kShellHeight, start.y};
    s.body.transform.yaw = yaw;
    s.velocity = dir * speed;
    s.ticks_left = static_cast<int>(std::ceil(range / speed * tuning::kTicksPerSecond));
    cur_.shells.push_back(s);
}

}  // namespace bz::game
