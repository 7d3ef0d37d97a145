// What the player sees and knows: awareness for the messages, radar blips, and the 3D frame
// interpolated between the last two ticks.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "core/angles.h"
#include "game/world/tuning.h"
#include "game/world/view_tuning.h"
#include "game/world/world.h"

namespace bz::game {

namespace {

// The target's offset in the player's view: x to the right, y straight ahead.
glm::dvec2 to_view(glm::dvec2 delta, double yaw) {
    const glm::dvec2 fwd{-std::sin(yaw), -std::cos(yaw)};
    const glm::dvec2 right{std::cos(yaw), -std::sin(yaw)};
    return {glm::dot(delta, right), glm::dot(delta, fwd)};
}

scene::Transform lerp(const Field& field, const scene::Transform& a, const scene::Transform& b,
                      double alpha) {
    scene::Transform t = b;
    const glm::dvec2 d = field.delta(ground(a.position), ground(b.position));
    const glm::dvec2 g = ground(a.position) + d * alpha;
    t.position = {g.x, a.position.y + (b.position.y - a.position.y) * alpha, g.y};
    t.yaw = a.yaw + wrap_angle(b.yaw - a.yaw) * alpha;
    t.pitch = a.pitch + wrap_angle(b.pitch - a.pitch) * alpha;
    t.roll = a.roll + wrap_angle(b.roll - a.roll) * alpha;
    return t;
}

// Finds the entity with the same id in the previous state (lists are sorted by id).
template <class T>
const T* find_id(const std::vector<T>& list, std::uint32_t id) {
    auto it = std::lower_bound(list.begin(), list.end(), id,
                               [](const T& e, std::uint32_t v) { return e.id < v; });
    return it != list.end() && it->id == id ? &*it : nullptr;
}

}  // namespace

double World::radar_range() const {
    return std::max(60.0, rules_.spawn_max_distance * 1.25);
}

Awareness World::awareness() const {
    Awareness a;
    a.motion_blocked = cur_.blocked_ticks > 0 && cur_.phase == Phase::playing;
    if (!cur_.hostile || cur_.phase != Phase::playing) return a;
    const scene::Entity& e = cur_.hostile->body;
    const glm::dvec2 d = field_.delta(player_ground(), ground(e.transform.position));
    const double dist = glm::length(d);
    const glm::dvec2 v = to_view(d, cur_.player.body.transform.yaw);
    const double bearing = std::atan2(v.x, v.y);  // > 0: to the right
    a.enemy_present = true;
    a.enemy_in_range = dist <= radar_range();
    if (std::abs(bearing) <= deg(tuning::kViewHalfAngleDeg)) {
        a.direction = EnemyDirection::ahead;
    } else if (std::abs(bearing) >= deg(tuning::kRearAngleDeg)) {
        a.direction = EnemyDirection::rear;
    } else {
        a.direction = bearing < 0.0 ? EnemyDirection::left : EnemyDirection::right;
    }
    // In the sights: the shell's path would pass through it before running out of range.
    const double half_width = e.collider.radius + tuning::kShellRadius;
    a.in_sights = v.y > 0.0 && v.y <= tuning::kShellRange && std::abs(v.x) < half_width * 0.8 &&
                  e.transform.position.y < tuning::kShellHeight + 1.5;
    return a;
}

std::vector<RadarBlip> World::radar_blips() const {
    std::vector<RadarBlip> out;
    // The saucer never shows on radar; only the hostile does.
    if (!cur_.hostile || cur_.phase != Phase::playing) return out;
    const glm::dvec2 d =
        field_.delta(player_ground(), ground(cur_.hostile->body.transform.position));
    const double dist = glm::length(d);
    if (dist > radar_range()) return out;
    out.push_back({to_view(d, cur_.player.body.transform.yaw), dist});
    return out;
}

double World::radar_sweep(double alpha) const {
    constexpr double period = tuning::kRadarSweepSeconds * tuning::kTicksPerSecond;
    const double t =
        static_cast<double>(prev_.tick) + alpha * static_cast<double>(cur_.tick - prev_.tick);
    return 2.0 * kPi * std::fmod(t, period) / period;
}

double World::eye_backoff(glm::dvec2 ground_pos, glm::dvec2 forward) const {
    using namespace view_tuning;
    // The nearest obstacle ahead, within the clearance.
    double ahead = kEyeClearance;
    for (double d = 0.0; d < kEyeClearance; d += kEyeSearchStep) {
        if (obstacle_at(ground_pos + forward * d, kEyeRadius) != nullptr) {
            ahead = d;
            break;
        }
    }
    double back = std::min(kEyeClearance - ahead, kMaxEyeBackoff);
    // Never into an obstacle behind, nor off the field's edge.
    while (back > 0.0) {
        const glm::dvec2 p = ground_pos - forward * back;
        if (obstacle_at(p, kEyeRadius) == nullptr && field_.contains(p, kEyeRadius)) break;
        back -= kEyeSearchStep;
    }
    return std::max(back, 0.0);
}

scene::FrameList World::interpolated_frame(double alpha, double fov_y_deg,
                                           double draw_distance) const {
    alpha = std::clamp(alpha, 0.0, 1.0);
    scene::FrameList f;
    f.style = style_;
    f.time_s =
        (static_cast<double>(prev_.tick) + alpha * static_cast<double>(cur_.tick - prev_.tick)) /
        tuning::kTicksPerSecond;
    f.seed = static_cast<std::uint32_t>(cur_.tick);
    const scene::Transform eye_t =
        lerp(field_, prev_.player.body.transform, cur_.player.body.transform, alpha);
    const glm::dvec3 fwd3 = eye_t.forward();
    const glm::dvec2 heading = glm::normalize(glm::dvec2(fwd3.x, fwd3.z));
    const glm::dvec2 tank_g = ground(eye_t.position);
    // Backed off along the heading, the reticle still marks where a shell goes.
    const glm::dvec2 eye_g = field_.wrap(tank_g - heading * eye_backoff(tank_g, heading));
    f.camera.eye = {eye_g.x, tuning::kEyeHeight, eye_g.y};
    f.camera.target = f.camera.eye + eye_t.forward();
    f.camera.fov_y_deg = fov_y_deg;
    f.camera.near = 0.3;
    f.camera.far = 5000.0;

    // Everything is drawn at its image nearest the eye, so the wrapping seam never shows.
    auto add = [&](const scene::Entity& e, scene::Transform t, bool occluder, float intensity) {
        const glm::dvec2 d = field_.delta(eye_g, ground(t.position));
        if (glm::length(d) > draw_distance) return;
        t.position.x = eye_g.x + d.x;
        t.position.z = eye_g.y + d.y;
        scene::DrawItem item;
        item.mesh = e.mesh;
        item.model = t.matrix();
        item.color = e.color;
        item.intensity = intensity;
        item.occluder = occluder;
        f.items.push_back(item);
    };

    for (const scene::Entity& o : obstacles_) add(o, o.transform, true, 1.0f);
    if (cur_.hostile) {
        const Hostile& h = *cur_.hostile;
        const bool same = prev_.hostile && prev_.hostile->id == h.id;
        add(h.body,
            same ? lerp(field_, prev_.hostile->body.transform, h.body.transform, alpha)
                 : h.body.transform,
            true, 1.0f);
    }
    if (cur_.saucer) {
        const Saucer& s = *cur_.saucer;
        const bool same = prev_.saucer && prev_.saucer->id == s.id;
        add(s.body,
            same ? lerp(field_, prev_.saucer->body.transform, s.body.transform, alpha)
                 : s.body.transform,
            true, 1.0f);
    }
    for (const Shell& s : cur_.shells) {
        const Shell* p = find_id(prev_.shells, s.id);
        add(s.body, p ? lerp(field_, p->body.transform, s.body.transform, alpha) : s.body.transform,
            false, 1.4f);
    }
    for (const Debris& d : cur_.debris) {
        const Debris* p = find_id(prev_.debris, d.id);
        // Fades over its last second.
        const float fade =
            std::min(1.0f, static_cast<float>(d.ticks_left) / tuning::kTicksPerSecond);
        // Young debris flashes overdriven (up to 3x): with the mame beam it defocuses into a
        // wide, soft burst, as an overdriven tube beam does.
        const float flash = std::clamp(
            static_cast<float>(d.ticks_left - (tuning::kDebrisTicks - 90)) / 30.0f, 0.0f, 1.0f);
        add(d.body, p ? lerp(field_, p->body.transform, d.body.transform, alpha) : d.body.transform,
            false, fade * (1.0f + 2.0f * flash));
    }
    return f;
}

}  // namespace bz::game
