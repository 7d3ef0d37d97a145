#include "game/world/tick_command.h"

#include <algorithm>
#include <cmath>

namespace bz::game {

namespace {

std::int8_t quantize(float v) {
    if (!std::isfinite(v)) return 0;
    return static_cast<std::int8_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * 127.0f));
}

}  // namespace

TickCommand TickCommand::from_drive(float forward, float turn) {
    TickCommand c;
    // Turning right drives the left tread harder; keep the pair within [-1, 1] while preserving
    // their ratio, as a tank with two tread levers would.
    float l = forward + turn;
    float r = forward - turn;
    const float m = std::max({1.0f, std::abs(l), std::abs(r)});
    c.left_tread = l / m;
    c.right_tread = r / m;
    return c;
}

PackedCommand pack(const TickCommand& c) {
    PackedCommand p;
    p.left = quantize(c.left_tread);
    p.right = quantize(c.right_tread);
    p.buttons = static_cast<std::uint8_t>(
        (c.fire ? button::fire : 0) | (c.start ? button::start : 0) |
        (c.pause ? button::pause : 0) | (c.up ? button::up : 0) | (c.down ? button::down : 0) |
        (c.left ? button::left : 0) | (c.right ? button::right : 0) | (c.back ? button::back : 0));
    return p;
}

TickCommand unpack(const PackedCommand& p) {
    TickCommand c;
    c.left_tread = static_cast<float>(p.left) / 127.0f;
    c.right_tread = static_cast<float>(p.right) / 127.0f;
    c.fire = (p.buttons & button::fire) != 0;
    c.start = (p.buttons & button::start) != 0;
    c.pause = (p.buttons & button::pause) != 0;
    c.up = (p.buttons & button::up) != 0;
    c.down = (p.buttons & button::down) != 0;
    c.left = (p.buttons & button::left) != 0;
    c.right = (p.buttons & button::right) != 0;
    c.back = (p.buttons & button::back) != 0;
    return c;
}

}  // namespace bz::game
