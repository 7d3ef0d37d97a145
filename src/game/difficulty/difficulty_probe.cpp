#include "game/difficulty/difficulty_probe.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "game/difficulty/autopilot.h"
#include "game/world/tuning.h"
#include "game/world/world.h"

namespace bz::game {

namespace {

// Whether the hostile stands inside the rear quarter: more than 135 degrees off the nose.
bool behind_player(const World& w) {
    const WorldState& s = w.state();
    const scene::Transform& me = s.player.body.transform;
    const glm::dvec2 d =
        w.field().delta(ground(me.position), ground(s.hostile->body.transform.position));
    const glm::dvec3 f = me.forward();
    const double ahead = d.x * f.x + d.y * f.z;
    const double right = d.x * -f.z + d.y * f.x;
    return std::abs(std::atan2(right, ahead)) > 135.0 * std::numbers::pi / 180.0;
}

}  // namespace

ProbeRun probe_game(const level::Level& level, const Assets& assets, Difficulty difficulty,
                    std::uint64_t seed, Pilot pilot, const ProbeOptions& options) {
    const level::Level playing = level_for(level, difficulty);
    World w(playing, seed, assets.factories(), assets.models(),
            options.lives > 0 ? options.lives : level.player_lives);
    ProbeRun run;
    const auto max_ticks =
        static_cast<std::uint64_t>(options.max_seconds * tuning::kTicksPerSecond);
    std::uint32_t last_hostile = 0;
    const int bonus_score = level.bonus_scores.empty() ? -1 : level.bonus_scores.front();
    auto now = [&] { return static_cast<double>(w.state().tick) * tuning::kDt; };
    while (w.state().tick < max_ticks && !w.game_over()) {
        w.step(pilot == Pilot::autopilot ? autopilot(w) : TickCommand{});
        const WorldState& s = w.state();
        if (s.hostile && s.hostile->id != last_hostile) {
            last_hostile = s.hostile->id;
            ++run.spawns;
            if (behind_player(w)) ++run.rear_spawns;
        }
        if (s.saucer && !run.saucer_seen_s) run.saucer_seen_s = now();
        if (!run.saucer_score_s && playing.enemies.saucer &&
            s.score >= playing.enemies.saucer_score) {
            run.saucer_score_s = now();
        }
        if (!run.bonus_score_s && bonus_score >= 0 && s.score >= bonus_score)
            run.bonus_score_s = now();
        for (const SoundEvent e : w.events()) {
            if (e == SoundEvent::bonus_life && !run.bonus_awarded_s) run.bonus_awarded_s = now();
            if (e == SoundEvent::player_death && !run.first_death_s) run.first_death_s = now();
        }
        if (run.first_death_s && options.stop_at_first_death) break;
    }
    run.score = w.score();
    run.seconds = now();
    return run;
}

ProbeSummary probe_summary(const level::Level& level, const Assets& assets, Difficulty difficulty,
                           Pilot pilot, int games, std::uint64_t first_seed,
                           const ProbeOptions& options) {
    ProbeSummary out;
    double total = 0.0;
    out.min_first_death_s = options.max_seconds;
    for (int i = 0; i < games; ++i) {
        const ProbeRun r = probe_game(level, assets, difficulty,
                                      first_seed + static_cast<std::uint64_t>(i), pilot, options);
        const double t = r.first_death_s.value_or(options.max_seconds);
        total += t;
        out.min_first_death_s = std::min(out.min_first_death_s, t);
        if (!r.first_death_s) ++out.survived;
        out.spawns += r.spawns;
        out.rear_spawns += r.rear_spawns;
        ++out.games;
    }
    out.mean_first_death_s = games > 0 ? total / games : 0.0;
    return out;
}

}  // namespace bz::game
