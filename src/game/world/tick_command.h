#pragma once
// One simulation tick's input, whatever device produced it. The simulation reads nothing else,
// so recording these (plus the seed) is enough to replay a game exactly.
#include <cstdint>

namespace bz::game {

struct TickCommand {
    float left_tread = 0.0f;   // -1 full reverse .. +1 full forward
    float right_tread = 0.0f;  // -1 full reverse .. +1 full forward
    bool fire = false;
    bool start = false;
    bool pause = false;
    // Menu navigation (screens and initials entry; the tank ignores them).
    bool up = false;
    bool down = false;
    bool left = false;
    bool right = false;
    bool back = false;

    // Tread values from a single stick or keys: forward and turn in [-1, 1], turn > 0 = right.
    static TickCommand from_drive(float forward, float turn);
};

// A command as the simulation sees it: treads quantized to 1/127 steps, buttons as bits. The
// world quantizes every command it steps, so a recorded command replays bit for bit.
struct PackedCommand {
    std::int8_t left = 0;
    std::int8_t right = 0;
    std::uint8_t buttons = 0;

    bool operator==(const PackedCommand&) const = default;
};

namespace button {
inline constexpr std::uint8_t fire = 1u << 0;
inline constexpr std::uint8_t start = 1u << 1;
inline constexpr std::uint8_t pause = 1u << 2;
inline constexpr std::uint8_t up = 1u << 3;
inline constexpr std::uint8_t down = 1u << 4;
inline constexpr std::uint8_t left = 1u << 5;
inline constexpr std::uint8_t right = 1u << 6;
inline constexpr std::uint8_t back = 1u << 7;
}  // namespace button

PackedCommand pack(const TickCommand& c);
TickCommand unpack(const PackedCommand& p);

}  // namespace bz::game
