#include "game/world/world.h"

#include <algorithm>
#include <cmath>

#include "core/angles.h"
#include "core/error.h"
#include "core/hash.h"
#include "game/world/collision.h"
#include "game/world/tuning.h"
#include "level/diagnostic.h"

namespace bz::game {

namespace {

scene::Placement placement_of(const level::ObjectDesc& o) {
    scene::Placement p;
    p.kind = o.kind;
    p.position = o.position;
    p.heading_deg = o.heading_deg;
    p.scale = o.scale;
    p.color = o.color;
    p.model = o.model;
    return p;
}

void hash_entity(Hasher& h, const scene::Entity& e) {
    const scene::Transform& t = e.transform;
    h.value(t.position.x);
    h.value(t.position.y);
    h.value(t.position.z);
    h.value(t.yaw);
    h.value(t.pitch);
    h.value(t.roll);
    h.value(t.scale);
    h.value(static_cast<std::uint8_t>(e.behaviour));
}

}  // namespace

double wrap_angle(double a) {
    a = std::fmod(a + kPi, 2.0 * kPi);
    if (a <= 0.0) a += 2.0 * kPi;
    return a - kPi;
}

void World::check_field(const level::Level& level) {
    if (!(level.field_size > 1.0) || !std::isfinite(level.field_size)) {
        throw UserError(level.file.string() + ": field_size must be a positive number");
    }
}

std::vector<scene::Entity> World::build_obstacles(const level::Level& level,
                                                  const scene::FactoryTable& factories,
                                                  const Field& field) {
    check_field(level);
    std::vector<scene::Entity> out;
    out.reserve(level.obstacles.size());
    for (const level::ObjectDesc& o : level.obstacles) {
        try {
            scene::Entity e = factories.create(placement_of(o));
            e.transform.position = glm::dvec3(o.position.x, o.position.y, o.position.z);
            const glm::dvec2 g = field.wrap(ground(e.transform.position));
            e.transform.position.x = g.x;
            e.transform.position.z = g.y;
            out.push_back(e);
        } catch (const UserError& err) {
            throw UserError(level::where(o.pos) + "error: " + err.what());
        }
    }
    return out;
}

World::World(const level::Level& level, std::uint64_t seed, const scene::FactoryTable& factories,
             ModelIds models, int lives)
    : field_(level.field_size, level.wrap),
      rules_(level.enemies),
      bonus_scores_(level.bonus_scores),
      models_(std::move(models)),
      obstacles_(build_obstacles(level, factories, field_)),
      grid_(obstacles_, field_),
      seed_(seed) {
    style_ = scene::style_from_name(level.render.style).value_or(scene::Style::vector);

    cur_.rng = Rng(seed);
    cur_.lives = std::clamp(lives, 1, tuning::kMaxLives);
    PlayerTank& p = cur_.player;
    p.body.behaviour = scene::Behaviour::player;
    p.body.collider = {
        scene::ColliderShape::circle, tuning::kPlayerRadius, {}, tuning::kTankHeight};
    const glm::dvec2 start = field_.wrap({level.player_start.x, level.player_start.z});
    p.body.transform.position = {start.x, 0.0, start.y};
    p.body.transform.yaw = wrap_angle(deg(level.player_heading_deg));
    cur_.hostile_spawn_ticks = tuning::kFirstSpawnTicks;
    cur_.saucer_spawn_ticks = static_cast<int>(
        tuning::kSaucerMinDelayTicks +
        cur_.rng.below(tuning::kSaucerMaxDelayTicks - tuning::kSaucerMinDelayTicks));
    prev_ = cur_;
}

void World::step(const TickCommand& command) {
    prev_ = cur_;
    events_.clear();
    const PackedCommand cmd = pack(command);
    ++cur_.tick;
    switch (cur_.phase) {
        case Phase::playing:
            step_player(cmd);
            step_spawning();
            step_hostile();
            step_saucer();
            step_shells();
            award_bonuses();
            break;
        case Phase::dying:
            step_dying();
            break;
        case Phase::game_over:
            break;
    }
    step_debris();
    if (cur_.blocked_ticks > 0) --cur_.blocked_ticks;

    // The radar pings as its sweep passes the hostile.
    if (cur_.phase == Phase::playing && !radar_blips().empty()) {
        const RadarBlip b = radar_blips().front();
        const double bearing = std::atan2(b.offset.x, b.offset.y);
        const double a0 = radar_sweep(0.0);
        const double a1 = radar_sweep(1.0);
        const double swept = std::fmod(a1 - a0 + 4.0 * kPi, 2.0 * kPi);
        const double to_blip = std::fmod(bearing - a0 + 4.0 * kPi, 2.0 * kPi);
        if (to_blip < swept) events_.push_back(SoundEvent::radar_blip);
    }
}

void World::add_score(int points) {
    cur_.score += points;
    award_bonuses();
}

void World::award_bonuses() {
    const int count = static_cast<int>(bonus_scores_.size());
    while (cur_.bonuses_awarded < count && cur_.score >= bonus_scores_[cur_.bonuses_awarded]) {
        ++cur_.bonuses_awarded;
        cur_.lives = std::min(cur_.lives + 1, tuning::kMaxLives);
        events_.push_back(SoundEvent::bonus_life);
    }
}

void World::step_dying() {
    if (--cur_.phase_ticks > 0) return;
    if (cur_.lives <= 0) {
        cur_.phase = Phase::game_over;
        return;
    }
    cur_.phase = Phase::playing;
    cur_.hostile_spawn_ticks = tuning::kRespawnTicks;
}

void World::kill_player() {
    if (cur_.phase != Phase::playing) return;
    events_.push_back(SoundEvent::player_death);
    cur_.phase = Phase::dying;
    cur_.phase_ticks = tuning::kDyingTicks;
    cur_.lives = std::max(0, cur_.lives - 1);
    cur_.crack_seed = cur_.rng.next_u32();
    cur_.hostile.reset();
    cur_.saucer.reset();
    cur_.shells.clear();
    cur_.player.speed = 0.0;
    cur_.player.turn_rate = 0.0;
    cur_.blocked_ticks = 0;
}

float World::engine_level() const {
    if (cur_.phase != Phase::playing) return 0.0f;
    const double moving = std::abs(cur_.player.speed) / tuning::kPlayerSpeed;
    const double turning = std::abs(cur_.player.turn_rate) / deg(tuning::kPlayerTurnDeg);
    return static_cast<float>(0.3 + 0.7 * std::min(1.0, std::max(moving, turning)));
}

std::uint64_t World::state_hash() const {
    Hasher h;
    const WorldState& s = cur_;
    h.value(s.tick);
    h.value(static_cast<std::uint8_t>(s.phase));
    h.value(s.phase_ticks);
    h.value(s.score);
    h.value(s.lives);
    h.value(s.bonuses_awarded);
    h.value(s.kills);
    h.value(s.rng.state());
    h.value(s.rng.increment());
    h.value(s.next_id);
    hash_entity(h, s.player.body);
    h.value(s.player.speed);
    h.value(s.player.turn_rate);
    h.value(s.player.fire_held);
    h.value(s.hostile.has_value());
    if (s.hostile) {
        const Hostile& e = *s.hostile;
        h.value(e.id);
        h.value(static_cast<std::uint8_t>(e.kind));
        hash_entity(h, e.body);
        h.value(static_cast<std::uint8_t>(e.mode));
        h.value(e.mode_ticks);
        h.value(e.mode_yaw);
        h.value(e.fire_cooldown);
        h.value(e.weave_phase);
        h.value(e.vertical_speed);
        h.value(e.provoked);
    }
    h.value(s.saucer.has_value());
    if (s.saucer) {
        h.value(s.saucer->id);
        hash_entity(h, s.saucer->body);
        h.value(s.saucer->velocity.x);
        h.value(s.saucer->velocity.y);
        h.value(s.saucer->ticks_left);
        h.value(s.saucer->turn_ticks);
    }
    h.value(s.shells.size());
    for (const Shell& sh : s.shells) {
        h.value(sh.id);
        hash_entity(h, sh.body);
        h.value(sh.velocity.x);
        h.value(sh.velocity.y);
        h.value(sh.ticks_left);
        h.value(sh.from_player);
    }
    h.value(s.debris.size());
    for (const Debris& d : s.debris) {
        h.value(d.id);
        hash_entity(h, d.body);
        h.value(d.velocity.x);
        h.value(d.velocity.y);
        h.value(d.velocity.z);
        h.value(d.spin.x);
        h.value(d.spin.y);
        h.value(d.spin.z);
        h.value(d.ticks_left);
    }
    h.value(s.hostile_spawn_ticks);
    h.value(s.saucer_spawn_ticks);
    h.value(s.blocked_ticks);
    h.value(s.crack_seed);
    // The static world too, so a replay against a different level cannot match by accident.
    h.value(field_.size());
    h.value(field_.wraps());
    h.value(obstacles_.size());
    for (const scene::Entity& o : obstacles_) hash_entity(h, o);
    return h.digest();
}

const scene::Entity* World::obstacle_at(glm::dvec2 p, double radius, double base_height) const {
    // The grid lists candidates in index order, so the first hit is the same one a scan over
    // every obstacle would find.
    grid_.near(p, radius, nearby_);
    for (const std::uint32_t k : nearby_) {
        const scene::Entity& o = obstacles_[k];
        const scene::Transform& t = o.transform;
        if (o.collider.height * t.scale + t.position.y <= base_height) continue;
        const glm::dvec2 off = field_.delta(ground(t.position), p);
        if (circle_hits(o.collider, t.yaw, t.scale, off, radius)) return &o;
    }
    return nullptr;
}

}  // namespace bz::game
