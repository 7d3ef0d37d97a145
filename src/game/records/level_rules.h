#pragma once
// A hash of everything in a level that the simulation reads (field, start, obstacles, enemy
// rules), and not its name, comments, look or sky: two levels with the same hash play alike,
// so their high scores compare. Fields added to the rules must be added here too.
#include <cstdint>

#include "level/level.h"

namespace bz::game {

std::uint64_t level_rules_hash(const level::Level& level);

}  // namespace bz::game
