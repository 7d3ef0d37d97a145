#pragma once
// Everything the simulation changes from tick to tick, as plain copyable data. The world keeps
// the previous and the current copy so that the display can interpolate between them, and
// state_hash() covers every field here.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "core/rng.h"
#include "scene/entity.h"

namespace bz::game {

enum class Phase : std::uint8_t {
    playing,
    dying,      // the screen has cracked; the next tank comes when the timer runs out
    game_over,  // no tanks left
};

enum class HostileKind : std::uint8_t { slow_tank, super_tank, missile };

enum class TankMode : std::uint8_t {
    approach,  // drive towards the player, off to one side
    attack,    // turn to face the player and fire
    evade,     // swerve away for a while
    detour,    // drive around an obstacle that blocked the way
};

struct PlayerTank {
    scene::Entity body;
    double speed = 0.0;      // units/s along forward(), this tick
    double turn_rate = 0.0;  // rad/s, this tick
    bool fire_held = false;  // fire fires on press, not while held
};

// The one hostile on the field: a tank, a super tank or a missile.
struct Hostile {
    std::uint32_t id = 0;
    HostileKind kind = HostileKind::slow_tank;
    scene::Entity body;
    TankMode mode = TankMode::approach;
    int mode_ticks = 0;           // ticks left in this mode
    double mode_yaw = 0.0;        // heading the mode steers towards (evade, detour) or side offset
    int fire_cooldown = 0;        // ticks until it may fire again
    double weave_phase = 0.0;     // missile zig-zag
    double vertical_speed = 0.0;  // missile hops
    bool provoked = false;        // the player fired while it was on the field (hold_fire)
};

struct Saucer {
    std::uint32_t id = 0;
    scene::Entity body;
    glm::dvec2 velocity{0.0};
    int ticks_left = 0;
    int turn_ticks = 0;  // ticks until it changes course
};

struct Shell {
    std::uint32_t id = 0;
    scene::Entity body;
    glm::dvec2 velocity{0.0};
    int ticks_left = 0;
    bool from_player = false;
};

struct Debris {
    std::uint32_t id = 0;
    scene::Entity body;
    glm::dvec3 velocity{0.0};
    glm::dvec3 spin{0.0};  // rad/s about yaw, pitch, roll
    int ticks_left = 0;
};

struct WorldState {
    std::uint64_t tick = 0;
    Phase phase = Phase::playing;
    int phase_ticks = 0;  // ticks left in dying
    int score = 0;
    int lives = 3;
    int bonuses_awarded = 0;
    int kills = 0;
    Rng rng;
    std::uint32_t next_id = 1;

    PlayerTank player;
    std::optional<Hostile> hostile;
    std::optional<Saucer> saucer;
    std::vector<Shell> shells;
    std::vector<Debris> debris;

    int hostile_spawn_ticks = 0;  // ticks until the next hostile may appear
    int saucer_spawn_ticks = 0;
    int blocked_ticks = 0;         // "MOTION BLOCKED BY OBJECT" stays up while > 0
    std::uint32_t crack_seed = 0;  // shape of the cracked screen of the last death
};

}  // namespace bz::game
