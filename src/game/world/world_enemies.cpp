// The hostile (slow tank, super tank or missile) and the saucer: when they appear, how they
// move, hunt and fire.
#include <algorithm>
#include <array>
#include <cmath>

#include "core/angles.h"
#include "game/world/collision.h"
#include "game/world/tuning.h"
#include "game/world/world.h"

namespace bz::game {

namespace {

// The yaw that faces along d (x, z).
double yaw_of(glm::dvec2 d) {
    return std::atan2(-d.x, -d.y);
}

// Turns yaw towards target by at most max_step; returns the remaining error.
double turn_towards(double& yaw, double target, double max_step) {
    const double err = wrap_angle(target - yaw);
    yaw = wrap_angle(yaw + std::clamp(err, -max_step, max_step));
    return wrap_angle(target - yaw);
}

int seconds_to_ticks(double seconds) {
    return static_cast<int>(std::lround(std::max(0.0, seconds) * tuning::kTicksPerSecond));
}

int ticks_between(Rng& rng, int lo, int hi) {
    return lo + static_cast<int>(rng.below(static_cast<std::uint32_t>(std::max(1, hi - lo))));
}

}  // namespace

void World::step_spawning() {
    if (cur_.hostile) return;
    if (cur_.hostile_spawn_ticks > 0) {
        --cur_.hostile_spawn_ticks;
        return;
    }
    if (!try_spawn_hostile()) cur_.hostile_spawn_ticks = 30;  // try again shortly
}

bool World::try_spawn_hostile() {
    const bool slow = rules_.slow_tank;
    const bool super = rules_.super_tank && cur_.score >= rules_.super_tank_score;
    const bool missile = rules_.missile && cur_.score >= rules_.missile_score;
    // Weighted pick among the kinds allowed at this score.
    const std::array<double, 3> weight{slow ? 1.0 : 0.0, super ? 1.0 : 0.0, missile ? 0.6 : 0.0};
    const double total = weight[0] + weight[1] + weight[2];
    if (total <= 0.0) return false;
    double pick = cur_.rng.uniform() * total;
    HostileKind kind = HostileKind::slow_tank;
    for (int i = 0; i < 3; ++i) {
        if (weight[i] <= 0.0) continue;
        kind = static_cast<HostileKind>(i);
        if (pick < weight[i]) break;
        pick -= weight[i];
    }

    const std::optional<glm::dvec2> p = spawn_spot(kind);
    if (!p) return false;
    place_hostile(kind, *p, yaw_of(field_.delta(*p, player_ground())));
    return true;
}

std::optional<glm::dvec2> World::spawn_spot(HostileKind kind) {
    const double radius =
        kind == HostileKind::missile ? tuning::kMissileRadius : tuning::kTankRadius;
    const double lo = std::max(10.0, rules_.spawn_min_distance);
    const double hi = std::max(lo, rules_.spawn_max_distance);
    // Bearings relative to the player's heading, clockwise: the rear quarter (135..225
    // degrees) gets only its share `spawn_rear_chance` of the spawns, so an enemy rarely
    // appears where the player cannot see it coming. The sector is drawn once, so places
    // blocked by obstacles in front do not push spawns round to the back.
    const double heading = cur_.player.body.transform.yaw;
    const bool rear = cur_.rng.uniform() < std::clamp(rules_.spawn_rear_chance, 0.0, 1.0);
    for (int attempt = 0; attempt < 40; ++attempt) {
        const double relative = rear ? cur_.rng.uniform(deg(135.0), deg(225.0))
                                     : cur_.rng.uniform(deg(-135.0), deg(135.0));
        // Clockwise from ahead is a turn to the right, which is negative yaw.
        const double yaw = heading - relative;
        const double dist = kind == HostileKind::missile ? hi : cur_.rng.uniform(lo, hi);
        const glm::dvec2 p =
            field_.wrap(player_ground() + glm::dvec2(-std::sin(yaw), -std::cos(yaw)) * dist);
        // Never inside (or touching) an obstacle, and on the field when it does not wrap.
        if (!field_.contains(p, radius + 1.0)) continue;
        if (obstacle_at(p, radius + 2.0) != nullptr) continue;
        return p;
    }
    return std::nullopt;
}

void World::place_hostile(HostileKind kind, glm::dvec2 position, double yaw) {
    Hostile h;
    h.id = cur_.next_id++;
    h.kind = kind;
    h.body.color = enemy_color_;
    h.body.transform.position = {position.x, 0.0, position.y};
    h.body.transform.yaw = wrap_angle(yaw);
    switch (kind) {
        case HostileKind::slow_tank:
            h.body.behaviour = scene::Behaviour::slow_tank;
            h.body.mesh = models_.slow_tank;
            break;
        case HostileKind::super_tank:
            h.body.behaviour = scene::Behaviour::super_tank;
            h.body.mesh = models_.super_tank;
            break;
        case HostileKind::missile:
            h.body.behaviour = scene::Behaviour::missile;
            h.body.mesh = models_.missile;
            h.body.transform.position.y = tuning::kMissileCruise;
            break;
    }
    const bool is_missile = kind == HostileKind::missile;
    h.body.collider = {scene::ColliderShape::circle,
                       is_missile ? tuning::kMissileRadius : tuning::kTankRadius,
                       {},
                       is_missile ? 1.0 : tuning::kTankHeight};
    // A new enemy waits two to three reloads, longer when calm, before its
    // first shot: time for the player to find it on the radar and turn.
    const double calm = 1.0 - std::clamp(rules_.aggression, 0.0, 1.0);
    h.fire_cooldown = seconds_to_ticks(rules_.fire_interval * (2.0 + calm)) +
                      ticks_between(cur_.rng, 0, tuning::kTicksPerSecond);
    h.mode = TankMode::approach;
    h.mode_ticks = ticks_between(cur_.rng, tuning::kApproachMinTicks, tuning::kApproachMaxTicks);
    h.mode_yaw = deg(cur_.rng.uniform(-tuning::kApproachOffsetDeg, tuning::kApproachOffsetDeg));
    h.weave_phase = cur_.rng.uniform(0.0, 2.0 * kPi);
    cur_.hostile = h;
    events_.push_back(SoundEvent::warning);
}

void World::spawn_hostile(HostileKind kind, glm::dvec2 view_offset, double yaw_towards_player_deg) {
    const glm::dvec2 p = field_.wrap(view_to_world(view_offset));
    place_hostile(kind, p, yaw_of(field_.delta(p, player_ground())) + deg(yaw_towards_player_deg));
}

void World::step_hostile() {
    if (!cur_.hostile) return;
    Hostile& h = *cur_.hostile;
    if (h.kind == HostileKind::missile) {
        step_missile(h);
    } else {
        step_tank(h);
    }
}

void World::step_tank(Hostile& h) {
    scene::Transform& t = h.body.transform;
    const bool super = h.kind == HostileKind::super_tank;
    const double speed = super ? tuning::kSuperTankSpeed : tuning::kTankSpeed;
    const double turn = deg(super ? tuning::kSuperTankTurnDeg : tuning::kTankTurnDeg) * tuning::kDt;
    const double aggression =
        std::clamp(rules_.aggression, 0.0, 1.0) * (super ? 1.0 : tuning::kSlowTankAggression);

    const glm::dvec2 to_player = field_.delta(ground(t.position), player_ground());
    const double dist = glm::length(to_player);
    const double face_player = yaw_of(to_player);
    if (h.fire_cooldown > 0) --h.fire_cooldown;
    if (h.mode_ticks > 0) --h.mode_ticks;

    TankCourse course = tank_course(h, dist, face_player, aggression);
    tank_dodge(h, to_player, aggression);
    const double err = turn_towards(t.yaw, course.yaw, turn);
    if (std::abs(err) > deg(tuning::kTurnOnTheSpotDeg)) course.throttle = 0.0;
    if (course.throttle != 0.0) tank_drive(h, speed * course.throttle);
    tank_fire(h, dist, face_player, aggression);
}

World::TankCourse World::tank_course(Hostile& h, double dist, double face_player,
                                     double aggression) {
    using namespace tuning;
    TankCourse course{face_player, 1.0};
    switch (h.mode) {
        case TankMode::approach:
            // Come in at an angle rather than head on, less so when close.
            course.yaw =
                face_player + h.mode_yaw * std::clamp(dist / kApproachStraightenDistance, 0.0, 1.0);
            if (dist < kEngageDistance) {
                h.mode = TankMode::attack;
                h.mode_ticks = ticks_between(cur_.rng, kAttackMinTicks, kAttackMaxTicks);
            } else if (h.mode_ticks == 0) {
                h.mode_ticks = ticks_between(cur_.rng, kApproachMinTicks, kApproachMaxTicks);
                h.mode_yaw = deg(cur_.rng.uniform(-kApproachOffsetDeg, kApproachOffsetDeg));
            }
            break;
        case TankMode::attack:
            course.throttle = dist > kHoldOffFar    ? kHoldOffFarThrottle
                              : dist < kHoldOffNear ? kHoldOffNearThrottle
                                                    : 0.0;
            if (dist > kEngageDistance * kDisengageFactor) {
                h.mode = TankMode::approach;
                h.mode_ticks = ticks_between(cur_.rng, kApproachMinTicks, kApproachMaxTicks);
            } else if (h.mode_ticks == 0) {
                if (cur_.rng.uniform() < 1.0 - kEvadeAggressionWeight * aggression) {
                    h.mode = TankMode::evade;
                    h.mode_ticks = ticks_between(cur_.rng, kEvadeMinTicks, kEvadeMaxTicks);
                    h.mode_yaw =
                        face_player + (cur_.rng.below(2) == 0 ? 1.0 : -1.0) * deg(kEvadeTurnDeg);
                } else {
                    h.mode_ticks = ticks_between(cur_.rng, kAttackMinTicks, kAttackMaxTicks);
                }
            }
            break;
        case TankMode::evade:
        case TankMode::detour:
            course.yaw = h.mode_yaw;
            if (h.mode_ticks == 0) {
                h.mode = TankMode::approach;
                h.mode_ticks = ticks_between(cur_.rng, kApproachMinTicks, kApproachMaxTicks);
                h.mode_yaw = deg(cur_.rng.uniform(-kApproachOffsetDeg, kApproachOffsetDeg));
            }
            break;
    }
    return course;
}

void World::tank_dodge(Hostile& h, glm::dvec2 to_player, double aggression) {
    using namespace tuning;
    const double yaw_p = cur_.player.body.transform.yaw;
    const double player_aim = wrap_angle(yaw_of(-to_player) - yaw_p);
    if (h.mode == TankMode::attack && std::abs(player_aim) < deg(kDodgeAimDeg) &&
        cur_.rng.uniform() < kDodgeChancePerTick * (1.0 - aggression)) {
        h.mode = TankMode::evade;
        h.mode_ticks = ticks_between(cur_.rng, kDodgeMinTicks, kDodgeMaxTicks);
        h.mode_yaw =
            h.body.transform.yaw + (cur_.rng.below(2) == 0 ? 1.0 : -1.0) * deg(kDodgeTurnDeg);
    }
}

void World::tank_drive(Hostile& h, double speed) {
    using namespace tuning;
    scene::Transform& t = h.body.transform;
    const glm::dvec3 fwd = t.forward();
    const glm::dvec2 next = ground(t.position) + glm::dvec2(fwd.x, fwd.z) * (speed * kDt);
    if (blocked(next, kTankRadius, false)) {
        const bool by_player = field_.distance(next, player_ground()) < kTankRadius + kPlayerRadius;
        if (!by_player && h.mode != TankMode::detour) {
            h.mode = TankMode::detour;
            h.mode_ticks = ticks_between(cur_.rng, kDetourMinTicks, kDetourMaxTicks);
            h.mode_yaw = t.yaw + (cur_.rng.below(2) == 0 ? 1.0 : -1.0) * deg(kDetourTurnDeg);
        }
    } else {
        const glm::dvec2 w = field_.wrap(next);
        t.position.x = w.x;
        t.position.z = w.y;
    }
}

void World::tank_fire(Hostile& h, double dist, double face_player, double aggression) {
    using namespace tuning;
    // Fire when the gun is on the player, within range, with no shell of its own in flight.
    const bool aimed =
        std::abs(wrap_angle(face_player - h.body.transform.yaw)) < deg(kAimToleranceDeg);
    const bool own_shell = std::any_of(cur_.shells.begin(), cur_.shells.end(),
                                       [](const Shell& s) { return !s.from_player; });
    const bool may_fire = !rules_.hold_fire || h.provoked;
    if (may_fire && h.mode == TankMode::attack && aimed && h.fire_cooldown == 0 && !own_shell &&
        dist < kEnemyShellRange) {
        const double error = deg(std::max(0.0, rules_.aim_error_deg));
        fire_shell(h.body, false, kEnemyShellSpeed, kEnemyShellRange,
                   cur_.rng.uniform(-error, error));
        events_.push_back(SoundEvent::enemy_shot);
        const double calm = 1.0 - aggression;
        h.fire_cooldown =
            seconds_to_ticks(rules_.fire_interval * (kReloadBase + kReloadCalm * calm)) +
            ticks_between(cur_.rng, 0, kTicksPerSecond);
    }
}

bool World::missile_is_nasty() const {
    return rules_.missile_nastier_after > 0 &&
           cur_.score >= rules_.missile_score + rules_.missile_nastier_after;
}

void World::step_missile(Hostile& h) {
    scene::Transform& t = h.body.transform;
    const glm::dvec2 here = ground(t.position);
    const glm::dvec2 to_player = field_.delta(here, player_ground());
    const double dist = glm::length(to_player);

    // Zig-zag in, straightening up for the final rush.
    h.weave_phase =
        std::fmod(h.weave_phase + 2.0 * kPi * tuning::kMissileWeaveHz * tuning::kDt, 2.0 * kPi);
    const double weave = dist > tuning::kMissileStraightDistance
                             ? deg(tuning::kMissileWeaveDeg) * std::sin(h.weave_phase)
                             : 0.0;
    // Faster and sharper once it has turned nastier.
    const bool nasty = missile_is_nasty();
    turn_towards(t.yaw, yaw_of(to_player) + weave,
                 deg(nasty ? tuning::kMissileNastyTurnDeg : tuning::kMissileTurnDeg) * tuning::kDt);

    // Hop: climb over anything ahead (or below), settle back to cruise height after.
    const glm::dvec3 fwd = t.forward();
    const glm::dvec2 dir{fwd.x, fwd.z};
    double wanted = tuning::kMissileCruise;
    for (double s = 0.0; s <= tuning::kMissileLookAhead; s += 1.0) {
        if (const scene::Entity* o = obstacle_at(here + dir * s, tuning::kMissileRadius)) {
            wanted = std::max(
                wanted, o->transform.position.y + o->collider.height * o->transform.scale + 0.5);
        }
    }
    const double climb = tuning::kMissileClimb * tuning::kDt;
    h.vertical_speed = std::clamp(wanted - t.position.y, -climb, climb) / tuning::kDt;
    t.position.y += h.vertical_speed * tuning::kDt;

    const glm::dvec2 next =
        here + dir * ((nasty ? tuning::kMissileNastySpeed : tuning::kMissileSpeed) * tuning::kDt);
    if (obstacle_at(next, tuning::kMissileRadius, t.position.y) == nullptr &&
        field_.contains(next, tuning::kMissileRadius)) {
        const glm::dvec2 w = field_.wrap(next);
        t.position.x = w.x;
        t.position.z = w.y;
    }

    if (field_.distance(ground(t.position), player_ground()) <
            tuning::kMissileRadius + tuning::kPlayerRadius &&
        t.position.y < tuning::kTankHeight + 0.5) {
        cur_.hostile.reset();  // it dies with the player; no points
        events_.push_back(SoundEvent::explosion);
        kill_player();
    }
}

void World::destroy_hostile() {
    if (!cur_.hostile) return;
    const Hostile& h = *cur_.hostile;
    int points = rules_.slow_tank_points;
    if (h.kind == HostileKind::super_tank) points = rules_.super_tank_points;
    if (h.kind == HostileKind::missile) points = rules_.missile_points;
    spawn_debris(h.body.transform.position, h.body.color, h.kind == HostileKind::missile ? 4 : 7,
                 1.0);
    cur_.hostile.reset();
    ++cur_.kills;
    cur_.hostile_spawn_ticks = tuning::kRespawnTicks;
    events_.push_back(SoundEvent::explosion);
    add_score(points);
}

void World::spawn_saucer(glm::dvec2 view_offset) {
    Saucer s;
    s.id = cur_.next_id++;
    s.body.behaviour = scene::Behaviour::saucer;
    s.body.mesh = models_.saucer;
    s.body.color = {0.4f, 1.0f, 0.8f};
    s.body.collider = {scene::ColliderShape::circle, tuning::kSaucerRadius, {}, 1.2};
    const glm::dvec2 p = field_.wrap(view_to_world(view_offset));
    s.body.transform.position = {p.x, tuning::kSaucerAltitude, p.y};
    s.ticks_left = tuning::kSaucerLifeTicks;
    s.turn_ticks = 0;
    cur_.saucer = s;
}

void World::step_saucer() {
    if (!cur_.saucer) {
        if (!rules_.saucer) return;
        // The delay runs from the start; below the saucer's score it waits at zero, so the
        // saucer comes as soon as the player reaches that score.
        if (cur_.saucer_spawn_ticks > 0) --cur_.saucer_spawn_ticks;
        if (cur_.saucer_spawn_ticks > 0 || cur_.score < rules_.saucer_score) return;
        const double bearing = cur_.rng.uniform(0.0, 2.0 * kPi);
        const double dist = cur_.rng.uniform(35.0, 70.0);
        spawn_saucer(glm::dvec2(std::sin(bearing), std::cos(bearing)) * dist);
        if (!field_.contains(ground(cur_.saucer->body.transform.position), tuning::kSaucerRadius)) {
            cur_.saucer.reset();  // off a closed field: try again later
            cur_.saucer_spawn_ticks = 60;
        }
        return;
    }
    Saucer& s = *cur_.saucer;
    scene::Transform& t = s.body.transform;
    if (--s.ticks_left <= 0) {
        cur_.saucer.reset();
        cur_.saucer_spawn_ticks =
            ticks_between(cur_.rng, tuning::kSaucerMinDelayTicks, tuning::kSaucerMaxDelayTicks);
        return;
    }
    if (--s.turn_ticks <= 0) {
        const double a = cur_.rng.uniform(0.0, 2.0 * kPi);
        s.velocity = glm::dvec2(std::cos(a), std::sin(a)) * tuning::kSaucerSpeed;
        s.turn_ticks = ticks_between(cur_.rng, 60, 150);
    }
    glm::dvec2 next = ground(t.position) + s.velocity * tuning::kDt;
    if (!field_.contains(next, tuning::kSaucerRadius)) {
        s.velocity = -s.velocity;
        next = ground(t.position);
    }
    next = field_.wrap(next);
    t.position.x = next.x;
    t.position.z = next.y;
    t.yaw = wrap_angle(t.yaw + 2.5 * tuning::kDt);
    // A gentle bob, from the tick count so it costs no state.
    t.position.y = tuning::kSaucerAltitude +
                   0.25 * std::sin(static_cast<double>(cur_.tick % 240) * (2.0 * kPi / 240.0));
}

void World::destroy_saucer() {
    if (!cur_.saucer) return;
    spawn_debris(cur_.saucer->body.transform.position, cur_.saucer->body.color, 5, 0.8);
    cur_.saucer.reset();
    cur_.saucer_spawn_ticks =
        ticks_between(cur_.rng, tuning::kSaucerMinDelayTicks, tuning::kSaucerMaxDelayTicks);
    events_.push_back(SoundEvent::explosion);
    add_score(rules_.saucer_points);
}

}  // namespace bz::game
