#pragma once
// Angles as the game states them (degrees in tuning tables and level files) and as the maths
// wants them (radians), in one place rather than a copy per source file.
#include <numbers>

namespace bz {

inline constexpr double kPi = std::numbers::pi;

constexpr double deg(double degrees) {
    return degrees * kPi / 180.0;
}

}  // namespace bz
