#pragma once
// The difficulty setting (easy, normal, arcade) as data: a level's enemy rules are written for
// "normal", and the other two scale them. The choice comes from --difficulty, else the
// player's settings file, else the level's own `[enemies] difficulty`.
#include <optional>
#include <string_view>

#include "level/level.h"

namespace bz::game {

using level::Difficulty;

std::string_view difficulty_name(Difficulty d);
std::optional<Difficulty> parse_difficulty(std::string_view text);  // "easy", "normal", "arcade"
inline constexpr std::string_view kDifficultyNames = "easy, normal, arcade";

// The rules `level` plays by at difficulty `d`:
//   easy   - calmer, slower-firing, less accurate enemies that appear farther off and rarely
//            behind the player;
//   normal - the level as written;
//   arcade - closer to the 1980 machine: relentless, quick, accurate, more often from behind.
// Thresholds, points, lives and bonus tanks are the level's at every difficulty.
level::EnemyRules rules_for(const level::EnemyRules& rules, double field_size, Difficulty d);
// The level with its enemy rules replaced by rules_for(...).
level::Level level_for(level::Level level, Difficulty d);

}  // namespace bz::game
