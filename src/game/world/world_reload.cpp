// A level edited while the game runs: the new static world goes in, and whatever it leaves
// inside an obstacle or off the field is moved to the nearest legal place.
#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "game/world/tuning.h"
#include "game/world/world.h"

namespace bz::game {

namespace {

// The search for a free place: rings this far apart, points at most this far apart on a ring.
constexpr double kSearchStep = 0.5;
constexpr int kMaxPointsPerRing = 256;

// A position on a field that does not wrap, pulled in so a circle of `radius` lies on it.
glm::dvec2 onto_field(glm::dvec2 p, const Field& field, double radius) {
    if (field.wraps()) return field.wrap(p);
    const double h = std::max(0.0, field.size() * 0.5 - radius);
    return {std::clamp(p.x, -h, h), std::clamp(p.y, -h, h)};
}

void set_ground(scene::Transform& t, glm::dvec2 g) {
    t.position.x = g.x;
    t.position.z = g.y;
}

}  // namespace

WorldReload World::reload_level(const level::Level& level, const scene::FactoryTable& factories) {
    Field field(level.field_size, level.wrap);
    std::vector<scene::Entity> obstacles = build_obstacles(level, factories, field);  // may throw

    field_ = field;
    // The nastier-missile rule is the game's, fixed when it started (a replay's may be 0).
    const int nastier_after = rules_.missile_nastier_after;
    rules_ = level.enemies;
    rules_.missile_nastier_after = nastier_after;
    bonus_scores_ = level.bonus_scores;
    obstacles_ = std::move(obstacles);
    grid_ = ObstacleGrid(obstacles_, field_);
    style_ = scene::style_from_name(level.render.style).value_or(scene::Style::vector);

    WorldReload out;
    out.player_moved = settle_player();
    out.hostile_moved = settle_hostile();
    settle_saucer_and_shells();
    for (Debris& d : cur_.debris) {
        set_ground(d.body.transform, field_.wrap(ground(d.body.transform.position)));
    }
    // Things may have jumped (a smaller field wraps them elsewhere): no sliding between the two.
    prev_ = cur_;
    return out;
}

glm::dvec2 World::free_spot_near(glm::dvec2 from, double radius) const {
    auto free = [&](glm::dvec2 p) {
        return field_.contains(p, radius) && obstacle_at(p, radius) == nullptr;
    };
    if (free(from)) return from;
    // Rings outwards, so the first free point is within one step of the nearest one.
    const double reach = field_.size();
    for (double r = kSearchStep; r <= reach; r += kSearchStep) {
        const int n = std::clamp(static_cast<int>(std::ceil(2.0 * kPi * r / kSearchStep)), 8,
                                 kMaxPointsPerRing);
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * kPi * i / n;
            const glm::dvec2 p = field_.wrap(from + glm::dvec2(std::sin(a), -std::cos(a)) * r);
            if (free(p)) return p;
        }
    }
    return from;
}

bool World::settle_player() {
    scene::Transform& t = cur_.player.body.transform;
    const glm::dvec2 was = player_ground();
    const glm::dvec2 now =
        free_spot_near(onto_field(was, field_, tuning::kPlayerRadius), tuning::kPlayerRadius);
    set_ground(t, now);
    return now != was;
}

bool World::settle_hostile() {
    if (!cur_.hostile) return false;
    Hostile& h = *cur_.hostile;
    scene::Transform& t = h.body.transform;
    const glm::dvec2 was = ground(t.position);
    const glm::dvec2 p = field_.wrap(was);
    set_ground(t, p);
    const double radius = h.body.collider.radius;
    // A missile in the middle of a hop over an obstacle is where it may be.
    const double base = h.kind == HostileKind::missile ? t.position.y : 0.0;
    const bool legal = field_.contains(p, radius) && obstacle_at(p, radius, base) == nullptr &&
                       field_.distance(p, player_ground()) >= radius + tuning::kPlayerRadius;
    if (legal) return p != was;
    // Placed anew as if it had just appeared (same kind, fresh orders); with nowhere legal
    // it goes, and the usual spawning brings one back shortly.
    const HostileKind kind = h.kind;
    cur_.hostile.reset();
    if (const std::optional<glm::dvec2> spot = spawn_spot(kind)) {
        const glm::dvec2 to_player = field_.delta(*spot, player_ground());
        place_hostile(kind, *spot, std::atan2(-to_player.x, -to_player.y));  // facing the tank
    } else {
        cur_.hostile_spawn_ticks = 30;
    }
    return true;
}

void World::settle_saucer_and_shells() {
    if (cur_.saucer) {
        scene::Transform& t = cur_.saucer->body.transform;
        const glm::dvec2 p = field_.wrap(ground(t.position));
        set_ground(t, p);
        if (!field_.contains(p, tuning::kSaucerRadius)) {
            cur_.saucer.reset();  // as when one would appear off a closed field
            cur_.saucer_spawn_ticks = 60;
        }
    }
    // Shells off a closed field are gone; one inside a new obstacle hits it on its next step.
    for (Shell& s : cur_.shells) {
        set_ground(s.body.transform, field_.wrap(ground(s.body.transform.position)));
    }
    std::erase_if(cur_.shells, [this](const Shell& s) {
        return !field_.contains(ground(s.body.transform.position));
    });
}

}  // namespace bz::game
