// Shells in flight (what they hit) and the debris of destroyed things.
#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "game/world/collision.h"
#include "game/world/tuning.h"
#include "game/world/world.h"

namespace bz::game {

void World::step_shells() {
    std::size_t keep = 0;
    for (std::size_t i = 0; i < cur_.shells.size(); ++i) {
        Shell s = cur_.shells[i];
        scene::Transform& t = s.body.transform;
        const glm::dvec2 from = ground(t.position);
        const glm::dvec2 to = from + s.velocity * tuning::kDt;
        bool alive = --s.ticks_left > 0 && field_.contains(to);

        // Obstacles stop shells; test a few points along the way so none slip through corners.
        if (alive) {
            for (int k = 1; k <= 3 && alive; ++k) {
                const glm::dvec2 p = from + (to - from) * (k / 3.0);
                if (obstacle_at(p, tuning::kShellRadius, t.position.y) != nullptr) {
                    alive = false;
                    events_.push_back(SoundEvent::shell_impact);
                }
            }
        }
        if (alive && s.from_player) {
            if (cur_.hostile) {
                const scene::Entity& e = cur_.hostile->body;
                const glm::dvec2 off_a = field_.delta(ground(e.transform.position), from);
                const glm::dvec2 off_b = off_a + (to - from);
                const bool low_enough = e.transform.position.y < tuning::kShellHeight + 1.5;
                if (low_enough && segment_hits(e.collider, e.transform.yaw, 1.0, off_a, off_b,
                                               tuning::kShellRadius)) {
                    alive = false;
                    destroy_hostile();
                }
            }
            if (alive && cur_.saucer) {
                const scene::Entity& e = cur_.saucer->body;
                const glm::dvec2 off_a = field_.delta(ground(e.transform.position), from);
                const glm::dvec2 off_b = off_a + (to - from);
                if (segment_hits(e.collider, e.transform.yaw, 1.0, off_a, off_b,
                                 tuning::kShellRadius)) {
                    alive = false;
                    destroy_saucer();
                }
            }
        } else if (alive) {
            const scene::Entity& e = cur_.player.body;
            const glm::dvec2 off_a = field_.delta(ground(e.transform.position), from);
            const glm::dvec2 off_b = off_a + (to - from);
            if (segment_hits(e.collider, e.transform.yaw, 1.0, off_a, off_b,
                             tuning::kShellRadius)) {
                kill_player();  // clears every shell
                return;
            }
        }
        if (!alive) continue;
        const glm::dvec2 w = field_.wrap(to);
        t.position.x = w.x;
        t.position.z = w.y;
        cur_.shells[keep++] = s;
    }
    cur_.shells.resize(keep);
}

void World::spawn_debris(const glm::dvec3& at, const glm::vec3& color, int pieces, double power) {
    const glm::dvec2 to_player = field_.delta(ground(at), player_ground());
    const double towards = std::atan2(to_player.y, to_player.x);
    for (int i = 0; i < pieces; ++i) {
        Debris d;
        d.id = cur_.next_id++;
        d.body.behaviour = scene::Behaviour::debris;
        d.body.color = color;
        d.body.mesh =
            models_.debris.empty()
                ? models_.shell
                : models_.debris[cur_.rng.below(static_cast<std::uint32_t>(models_.debris.size()))];
        d.body.transform.position = at + glm::dvec3(0.0, 0.8, 0.0);
        // The first piece flies at the player, as in the arcade game; the rest scatter.
        const double a =
            i == 0 ? towards + cur_.rng.uniform(-0.15, 0.15) : cur_.rng.uniform(0.0, 2.0 * kPi);
        const double out = (i == 0 ? 9.0 : cur_.rng.uniform(2.0, 7.0)) * power;
        d.velocity = {std::cos(a) * out, cur_.rng.uniform(5.0, 11.0) * power, std::sin(a) * out};
        d.spin = {cur_.rng.uniform(-6.0, 6.0), cur_.rng.uniform(-6.0, 6.0),
                  cur_.rng.uniform(-6.0, 6.0)};
        d.body.transform.yaw = cur_.rng.uniform(-kPi, kPi);
        d.ticks_left = tuning::kDebrisTicks - static_cast<int>(cur_.rng.below(60));
        cur_.debris.push_back(d);
    }
}

void World::step_debris() {
    std::size_t keep = 0;
    for (std::size_t i = 0; i < cur_.debris.size(); ++i) {
        Debris d = cur_.debris[i];
        if (--d.ticks_left <= 0) continue;
        scene::Transform& t = d.body.transform;
        // Parabolas: constant horizontal speed, gravity pulling down, until they land.
        d.velocity.y -= tuning::kGravity * tuning::kDt;
        t.position += d.velocity * tuning::kDt;
        t.yaw = wrap_angle(t.yaw + d.spin.x * tuning::kDt);
        t.pitch = wrap_angle(t.pitch + d.spin.y * tuning::kDt);
        t.roll = wrap_angle(t.roll + d.spin.z * tuning::kDt);
        if (t.position.y <= 0.0) {
            t.position.y = 0.0;
            d.velocity = glm::dvec3(0.0);
            d.spin = glm::dvec3(0.0);
        }
        const glm::dvec2 w = field_.wrap(ground(t.position));
        t.position.x = w.x;
        t.position.z = w.y;
        cur_.debris[keep++] = d;
    }
    cur_.debris.resize(keep);
}

}  // namespace bz::game
