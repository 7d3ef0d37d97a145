#pragma once
// A simple gunner that turns towards the nearest target and fires when it is in the sights:
// drives the attract-mode demo, and tests that need a game played for a while.
#include "game/world/tick_command.h"
#include "game/world/world.h"

namespace bz::game {

TickCommand autopilot(const World& world);

}  // namespace bz::game
