#pragma once
// The 1980 machine's operator settings (its DIP switches) as rules over a level: tanks at the
// start, the score from which missiles come, and the bonus tanks. Each unset rule keeps the
// level's own. Replays record them and high-score tables are kept apart by them (the rules
// hash of the level as played), so a five-tank score never sits among three-tank ones.
#include <optional>
#include <string>

#include "level/level.h"

namespace bz::game {

// The second bonus tank of every bonus setting (the switches choose only the first).
inline constexpr int kArcadeSecondBonus = 100000;

struct ArcadeRules {
    std::optional<int> lives;
    std::optional<int> missile_score;
    std::optional<int> bonus_score;  // the first bonus tank; 0: no bonus tanks at all
    bool any() const { return lives || missile_score || bonus_score; }
    bool operator==(const ArcadeRules&) const = default;
};

// The level as these rules play it.
level::Level with_arcade_rules(level::Level level, const ArcadeRules& rules);

// How the high-score table names the rules that differ from the level's ("5 TANKS,
// MISSILES 30000, NO BONUS"); empty when none is set.
std::string arcade_label(const ArcadeRules& rules);

}  // namespace bz::game
