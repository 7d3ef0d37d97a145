#pragma once
// Shared helpers for the game tests: levels made to order and a world built on real assets.
#include <functional>
#include <memory>

#include "game/assets/assets.h"
#include "game/default_level.h"
#include "game/world/tick_command.h"
#include "game/world/world.h"

namespace bz::game::test {

// One set of meshes for every test in the binary (building them is the slow part).
inline const Assets& shared_assets() {
    static const Assets assets(default_level().backdrop);
    return assets;
}

// An open field with no obstacles, no enemies appearing by themselves and no saucer, so a
// test places exactly what it needs.
inline level::Level empty_level() {
    level::Level lv;
    lv.file = "<test>";
    lv.field_size = 400.0;
    lv.enemies.slow_tank = false;
    lv.enemies.super_tank = false;
    lv.enemies.missile = false;
    lv.enemies.saucer = false;
    lv.enemies.aggression = 0.0;
    return lv;
}

inline level::ObjectDesc object(const char* kind, double x, double z) {
    level::ObjectDesc o;
    o.kind = kind;
    o.position = {x, 0.0, z};
    return o;
}

inline World make_world(const level::Level& lv, std::uint64_t seed = 1, int lives = 3) {
    const Assets& a = shared_assets();
    return World(lv, seed, a.factories(), a.models(), lives);
}

inline TickCommand drive(float left, float right, bool fire = false) {
    TickCommand c;
    c.left_tread = left;
    c.right_tread = right;
    c.fire = fire;
    return c;
}

// Steps until `done` or `max_ticks`; returns the ticks run. Every tick's events pass to `seen`.
inline int run_until(World& w, const std::function<TickCommand(const World&)>& input,
                     const std::function<bool(const World&)>& done, int max_ticks,
                     const std::function<void(SoundEvent)>& seen = nullptr) {
    for (int i = 0; i < max_ticks; ++i) {
        if (done(w)) return i;
        w.step(input(w));
        if (seen) {
            for (SoundEvent e : w.events()) seen(e);
        }
    }
    return max_ticks;
}

// Fires once (press then release) and lets the shell fly for `ticks`.
inline void fire_and_wait(World& w, int ticks, std::vector<SoundEvent>* events = nullptr) {
    for (int i = 0; i < ticks; ++i) {
        w.step(drive(0, 0, i == 0));
        if (events) events->insert(events->end(), w.events().begin(), w.events().end());
    }
}

inline bool has(const std::vector<SoundEvent>& v, SoundEvent e) {
    return std::find(v.begin(), v.end(), e) != v.end();
}

}  // namespace bz::game::test
