#include "game/records/level_rules.h"

#include "core/hash.h"

namespace bz::game {

std::uint64_t level_rules_hash(const level::Level& lv) {
    Hasher h;
    h.value(lv.field_size);
    h.value(lv.wrap);
    h.value(lv.player_start.x);
    h.value(lv.player_start.z);
    h.value(lv.player_heading_deg);
    h.value(lv.obstacles.size());
    for (const level::ObjectDesc& o : lv.obstacles) {
        h.text(o.kind);
        h.text(o.model.filename().string());  // where the folder sits does not matter
        h.value(o.position.x);
        h.value(o.position.y);
        h.value(o.position.z);
        h.value(o.heading_deg);
        h.value(o.scale);
    }
    const level::EnemyRules& e = lv.enemies;
    h.value(e.slow_tank);
    h.value(e.super_tank);
    h.value(e.missile);
    h.value(e.saucer);
    h.value(e.super_tank_score);
    h.value(e.missile_score);
    h.value(e.spawn_min_distance);
    h.value(e.spawn_max_distance);
    h.value(e.aggression);
    h.value(e.saucer_score);
    h.value(e.spawn_rear_chance);
    h.value(e.fire_interval);
    h.value(e.aim_error_deg);
    h.value(e.hold_fire);
    h.value(e.slow_tank_points);
    h.value(e.super_tank_points);
    h.value(e.missile_points);
    h.value(e.saucer_points);
    h.value(static_cast<std::uint8_t>(e.difficulty));
    h.value(lv.player_lives);
    h.value(lv.bonus_scores.size());
    for (const int b : lv.bonus_scores) h.value(b);
    return h.digest();
}

}  // namespace bz::game
