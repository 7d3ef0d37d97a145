// Simulation speed: one World::step on the built-in level with the autopilot playing, and
// verifying a recorded replay (the goal: minutes of play verify in well under a second).
#include <benchmark/benchmark.h>

#include "game/assets/assets.h"
#include "game/default_level.h"
#include "game/difficulty/autopilot.h"
#include "game/records/replay.h"
#include "game/world/world.h"

namespace {

using namespace bz::game;

const Assets& assets() {
    static const Assets a(default_level().backdrop);
    return a;
}

void BM_WorldStep(benchmark::State& state) {
    const auto level = default_level();
    World w(level, 1, assets().factories(), assets().models(), 9);
    for (auto _ : state) {
        if (w.game_over())
            w = World(level, w.seed() + 1, assets().factories(), assets().models(), 9);
        w.step(autopilot(w));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_WorldStep);

void BM_StateHash(benchmark::State& state) {
    World w(default_level(), 1, assets().factories(), assets().models(), 9);
    for (int i = 0; i < 600; ++i) w.step(autopilot(w));
    for (auto _ : state) benchmark::DoNotOptimize(w.state_hash());
}
BENCHMARK(BM_StateHash);

// A recording of `minutes` of autopilot play (it gets new tanks to keep going).
replay::Replay recording(int minutes) {
    const auto level = default_level();
    World w(level, 7, assets().factories(), assets().models(), 9);
    replay::Header h;
    h.seed = 7;
    h.lives = 9;
    h.level = kBuiltinLevelName;
    replay::Recorder rec(h);
    for (int i = 0; i < minutes * 3600 && !w.game_over(); ++i) {
        const TickCommand c = autopilot(w);
        w.step(c);
        rec.record(c, w);
    }
    return rec.finish(w);
}

void BM_VerifyReplay(benchmark::State& state) {
    const replay::Replay r = recording(static_cast<int>(state.range(0)));
    const auto level = default_level();
    for (auto _ : state) {
        const auto v = replay::verify(r, level, assets());
        if (!v.ok) state.SkipWithError("replay did not verify");
    }
    state.counters["ticks"] = static_cast<double>(r.commands.size());
    state.counters["play_s"] = static_cast<double>(r.commands.size()) / 60.0;
}
BENCHMARK(BM_VerifyReplay)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_GameFrame(benchmark::State& state) {
    World w(default_level(), 1, assets().factories(), assets().models(), 9);
    for (int i = 0; i < 600; ++i) w.step(autopilot(w));
    for (auto _ : state) benchmark::DoNotOptimize(w.interpolated_frame(0.5));
}
BENCHMARK(BM_GameFrame);

}  // namespace

BENCHMARK_MAIN();
