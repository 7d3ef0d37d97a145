#pragma once
// How the player's view is placed: presentation only, never part of the simulation, so
// changing these changes no replay (unlike tuning.h).
namespace bz::game::view_tuning {

// Driven flush against an obstacle (the tank's centre kPlayerRadius from it), the eye would
// sit 1.6 units from a face 5 wide and high: the face fills the view and hides everything.
// The eye backs off along the tank's heading until the nearest obstacle ahead is at least
// this far, so its side and bottom edges stay in view at the game's 45 degree field of view
// (a 5-wide face needs 3.4 units at 16:9; the margin covers 4:3).
inline constexpr double kEyeClearance = 4.5;
// At most this far behind the centre, and never into an obstacle or off the field.
inline constexpr double kMaxEyeBackoff = 3.0;
// The eye's own size for those tests: the near plane's half-diagonal at 0.3 is about 0.4.
inline constexpr double kEyeRadius = 0.45;
// Step of the search along the heading.
inline constexpr double kEyeSearchStep = 0.02;

}  // namespace bz::game::view_tuning
