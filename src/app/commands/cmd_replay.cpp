// beamzone replay FILE [--verify] [--level LEVEL]: inspects a replay, or re-simulates it
// headless and checks every recorded state hash.
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/replay_level.h"
#include "cli/replay_args.h"
#include "core/error.h"
#include "core/hash.h"
#include "core/io/output_path.h"
#include "core/paths.h"
#include "core/text/printable.h"
#include "game/assets/assets.h"
#include "game/default_level.h"
#include "game/difficulty/autopilot.h"
#include "game/difficulty/difficulty.h"
#include "game/records/replay.h"
#include "level/loader.h"

namespace bz::app {

namespace {

namespace fs = std::filesystem;

level::Level load_level_or_report(const fs::path& path, bool& ok) {
    level::LoadResult loaded = level::load_level_file(path);
    ok = loaded.ok();
    if (!ok) {
        for (const level::Diagnostic& d : loaded.errors)
            std::fprintf(stderr, "%s\n", level::format(d).c_str());
        return {};
    }
    return std::move(*loaded.level);
}

int record_demo(const ReplayOptions& o) {
    const fs::path inputs[] = {o.level};
    check_output_file("replay --record-demo", o.file, kReplayOutput, inputs, o.overwrite);
    level::Level lv = game::default_level();
    std::string name = game::kBuiltinLevelName;
    if (!o.level.empty()) {
        bool ok = false;
        lv = load_level_or_report(o.level, ok);
        if (!ok) return 1;
        name = o.level;
    }
    const game::Assets assets(lv);
    // Nine tanks so the demo keeps playing for long recordings.
    constexpr int kLives = 9;
    const level::Difficulty difficulty = o.difficulty.value_or(lv.enemies.difficulty);
    game::World world(game::level_for(lv, difficulty), o.seed, assets.factories(), assets.models(),
                      kLives);
    game::replay::Header h;
    h.difficulty = difficulty;
    h.seed = o.seed;
    h.level = name;
    h.level_hash = game::replay::level_hash(lv);
    h.lives = kLives;
    h.missile_nastier_after = world.rules().missile_nastier_after;
    game::replay::Recorder rec(h);
    const int ticks = o.record_seconds * 60;
    for (int i = 0; i < ticks && !world.game_over(); ++i) {
        const game::TickCommand c = game::autopilot(world);
        world.step(c);
        rec.record(c, world);
    }
    game::replay::save(o.file, rec.finish(world));
    std::printf("%s: recorded %" PRIu64 " ticks, score %d\n", o.file.c_str(), world.state().tick,
                world.score());
    return 0;
}

int run(const ReplayOptions& o) {
    if (o.record_seconds > 0) return record_demo(o);
    const game::replay::Replay r = game::replay::load(o.file);
    const game::replay::Header& h = r.header;
    const double seconds = static_cast<double>(r.commands.size()) / 60.0;

    level::Level lv;
    std::string level_label;
    if (o.level.empty() && h.level == game::kBuiltinLevelName) {
        lv = game::default_level();
        level_label = h.level;
    } else {
        const fs::path path =
            o.level.empty() ? replay_level_path(h.level, o.file) : fs::path(o.level);
        bool ok = false;
        lv = load_level_or_report(path, ok);
        if (!ok) {
            std::fprintf(stderr, "%s: error: the level the replay needs (%s) did not load\n",
                         o.file.c_str(), path.string().c_str());
            return 1;
        }
        level_label = path.string();
    }

    if (!o.verify) {
        std::printf("%s: beamzone replay recorded by %s\n", o.file.c_str(), h.version.c_str());
        std::printf("  level       %s (hash %s)\n", h.level.c_str(), hex(h.level_hash).c_str());
        std::printf("  seed        %" PRIu64 "\n", h.seed);
        std::printf("  lives       %d\n", h.lives);
        std::printf("  difficulty  %s\n", std::string(game::difficulty_name(h.difficulty)).c_str());
        std::printf("  ticks       %zu (%.1f s of play)\n", r.commands.size(), seconds);
        std::printf("  hashes      %zu (every %d ticks)\n", r.checks.size(), h.hash_interval);
        return 0;
    }

    if (h.version != BEAMZONE_VERSION) {
        std::fprintf(
            stderr, "%s: warning: recorded by beamzone %s, this is %s; the simulation may differ\n",
            o.file.c_str(), h.version.c_str(), BEAMZONE_VERSION);
    }
    const std::uint64_t now_hash = game::replay::level_hash(lv);
    if (now_hash != h.level_hash) {
        std::fprintf(stderr,
                     "%s: error: level %s is not the one the replay was recorded on (hash %s, "
                     "recorded %s)\n",
                     o.file.c_str(), level_label.c_str(), hex(now_hash).c_str(),
                     hex(h.level_hash).c_str());
        return 1;
    }

    const std::string missing = game::replay::missing_state_hashes(r);
    if (!missing.empty() && !o.inputs_only) {
        std::fprintf(stderr,
                     "%s: error: cannot verify: %s, so re-simulating it would prove nothing "
                     "(pass --inputs-only to replay its commands anyway)\n",
                     printable(o.file).c_str(), missing.c_str());
        return 1;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const game::Assets assets(lv);
    const game::replay::VerifyResult v = game::replay::verify(r, lv, assets);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!v.ok) {
        std::fprintf(stderr,
                     "%s: error: state hash mismatch at tick %" PRIu64
                     " (%.2f s): recorded %s, "
                     "re-simulated %s (%zu earlier hashes matched)\n",
                     o.file.c_str(), v.mismatch->tick, static_cast<double>(v.mismatch->tick) / 60.0,
                     hex(v.mismatch->expected).c_str(), hex(v.mismatch->actual).c_str(),
                     v.checks_passed);
        return 1;
    }
    std::printf("%s: ok: %" PRIu64
                " ticks (%.1f s of play), %zu state hashes match (verified in "
                "%.1f ms, building the level included)%s\n",
                printable(o.file).c_str(), v.ticks, seconds, v.checks_passed, ms,
                missing.empty() ? "" : "; inputs only: not every interval had a state hash");
    return 0;
}

}  // namespace

int cmd_replay(Args args) {
    int exit_code = 0;
    const std::optional<ReplayOptions> parsed =
        parse_command("replay", args, kReplayUsage, parse_replay_args, &exit_code);
    if (!parsed) return exit_code;
    const ReplayOptions& o = *parsed;
    try {
        return run(o);
    } catch (const UserError& e) {
        // Replay and level messages already name the file (and line).
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}

}  // namespace bz::app
