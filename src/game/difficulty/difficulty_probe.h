#pragma once
// Measures how a level plays at a difficulty, headless and deterministic: one game per seed,
// driven by an idle player (never touches the controls) or by the attract-mode autopilot.
// `beamzone difficulty` prints the table; the tests hold the shipped levels to their goals.
#include <cstdint>
#include <optional>
#include <vector>

#include "game/assets/assets.h"
#include "game/difficulty/difficulty.h"
#include "level/level.h"

namespace bz::game {

enum class Pilot : std::uint8_t { idle, autopilot };

struct ProbeRun {
    std::optional<double> first_death_s;    // none: alive after the time limit
    int spawns = 0;                         // hostiles that appeared
    int rear_spawns = 0;                    // ... of them inside the 90 degrees behind the player
    std::optional<double> saucer_score_s;   // when the score reached the saucer's score
    std::optional<double> saucer_seen_s;    // when a saucer first appeared
    std::optional<double> bonus_score_s;    // when the score reached the first bonus score
    std::optional<double> bonus_awarded_s;  // when the first bonus tank was awarded
    int score = 0;
    double seconds = 0.0;  // simulated
};

struct ProbeOptions {
    double max_seconds = 120.0;
    bool stop_at_first_death = true;  // false: play on until game over or the time limit
    int lives = 0;                    // 0: the level's
};

// Plays one game. `assets` must be built for `level` (Assets(level.backdrop), and every model
// the level names imports on first use).
ProbeRun probe_game(const level::Level& level, const Assets& assets, Difficulty difficulty,
                    std::uint64_t seed, Pilot pilot, const ProbeOptions& options = {});

struct ProbeSummary {
    int games = 0;
    double mean_first_death_s = 0.0;  // survivors count as max_seconds
    double min_first_death_s = 0.0;
    int survived = 0;  // games with no death within max_seconds
    int spawns = 0;
    int rear_spawns = 0;
    double rear_share() const { return spawns ? double(rear_spawns) / spawns : 0.0; }
};

// Games with seeds first_seed .. first_seed + games - 1.
ProbeSummary probe_summary(const level::Level& level, const Assets& assets, Difficulty difficulty,
                           Pilot pilot, int games, std::uint64_t first_seed = 1,
                           const ProbeOptions& options = {});

}  // namespace bz::game
