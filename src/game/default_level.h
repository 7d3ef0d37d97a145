#pragma once
// A level that needs no file: for tests, benchmarks and a game started without a level.
#include "level/level.h"

namespace bz::game {

// The name replays record for the built-in level instead of a file path.
inline constexpr const char* kBuiltinLevelName = "builtin:default";

// Obstacles scattered over a 400-unit wrapping field (none near the start), the default
// mountain range, a volcano and the moon, and the default enemy rules.
level::Level default_level();

}  // namespace bz::game
