#include "game/difficulty/difficulty.h"

#include <algorithm>

namespace bz::game {

namespace {

// What each difficulty multiplies. Normal is the identity, so a level means what it says.
struct Scale {
    double aggression;
    double fire_interval;
    double aim_error;
    double spawn_distance;
    double rear_chance;
};

// Arcade sends more enemies from behind, as the original did from every side, but still at
// most about a quarter of them with the default rear chance.
constexpr Scale kEasy{0.6, 1.6, 1.6, 1.2, 0.5};
constexpr Scale kNormal{1.0, 1.0, 1.0, 1.0, 1.0};
constexpr Scale kArcade{1.5, 0.5, 0.35, 0.85, 1.5};

const Scale& scale_of(Difficulty d) {
    switch (d) {
        case Difficulty::easy:
            return kEasy;
        case Difficulty::arcade:
            return kArcade;
        case Difficulty::normal:
            break;
    }
    return kNormal;
}

}  // namespace

std::string_view difficulty_name(Difficulty d) {
    switch (d) {
        case Difficulty::easy:
            return "easy";
        case Difficulty::arcade:
            return "arcade";
        case Difficulty::normal:
            break;
    }
    return "normal";
}

std::optional<Difficulty> parse_difficulty(std::string_view text) {
    for (const Difficulty d : {Difficulty::easy, Difficulty::normal, Difficulty::arcade}) {
        if (text == difficulty_name(d)) return d;
    }
    return std::nullopt;
}

level::EnemyRules rules_for(const level::EnemyRules& rules, double field_size, Difficulty d) {
    const Scale& s = scale_of(d);
    level::EnemyRules r = rules;
    r.aggression = std::clamp(rules.aggression * s.aggression, 0.0, 1.0);
    r.fire_interval = rules.fire_interval * s.fire_interval;
    r.aim_error_deg = rules.aim_error_deg * s.aim_error;
    // Spawn distances stay inside half the field, as the level loader keeps them.
    const double half = field_size / 2.0;
    r.spawn_max_distance = std::min(rules.spawn_max_distance * s.spawn_distance, half);
    r.spawn_min_distance =
        std::min(rules.spawn_min_distance * s.spawn_distance, r.spawn_max_distance);
    r.spawn_rear_chance = std::clamp(rules.spawn_rear_chance * s.rear_chance, 0.0, 1.0);
    r.difficulty = d;
    return r;
}

level::Level level_for(level::Level level, Difficulty d) {
    level.enemies = rules_for(level.enemies, level.field_size, d);
    return level;
}

}  // namespace bz::game
