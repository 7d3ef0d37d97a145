#include "game/difficulty/arcade_rules.h"

namespace bz::game {

level::Level with_arcade_rules(level::Level level, const ArcadeRules& rules) {
    if (rules.lives) level.player_lives = *rules.lives;
    if (rules.missile_score) level.enemies.missile_score = *rules.missile_score;
    if (rules.bonus_score) {
        level.bonus_scores.clear();
        if (*rules.bonus_score > 0) {
            level.bonus_scores.push_back(*rules.bonus_score);
            if (*rules.bonus_score < kArcadeSecondBonus) {
                level.bonus_scores.push_back(kArcadeSecondBonus);
            }
        }
    }
    return level;
}

std::string arcade_label(const ArcadeRules& rules) {
    std::string out;
    auto add = [&out](const std::string& part) { out += (out.empty() ? "" : ", ") + part; };
    if (rules.lives) add(std::to_string(*rules.lives) + " TANKS");
    if (rules.missile_score) add("MISSILES " + std::to_string(*rules.missile_score));
    if (rules.bonus_score) {
        add(*rules.bonus_score > 0 ? "BONUS " + std::to_string(*rules.bonus_score) : "NO BONUS");
    }
    return out;
}

}  // namespace bz::game
