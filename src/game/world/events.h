#pragma once
// What the simulation tells the sound synth about one tick.
#include <cstdint>
#include <vector>

namespace bz::game {

enum class SoundEvent : std::uint8_t {
    shot,          // the player fired
    enemy_shot,    // a hostile fired
    explosion,     // something was destroyed (a hostile, the saucer)
    shell_impact,  // a shell hit an obstacle
    player_death,  // the player's tank was hit: the screen cracks
    radar_blip,    // the radar sweep passed over the hostile
    warning,       // a hostile appeared, or a missile is closing in
    bonus_life,    // an extra tank was awarded
    blocked,       // the player drove into an obstacle
};

struct SoundFrame {
    float engine = 0.0f;  // 0 = off, ~0.3 idling, 1 = full speed
    std::vector<SoundEvent> events;
};

}  // namespace bz::game
