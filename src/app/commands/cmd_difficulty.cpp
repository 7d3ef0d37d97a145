// `beamzone difficulty`: the difficulty table. For each level and difficulty, 20 (--seeds)
// headless games from the first tick: the time to the first death for an idle player and for
// the autopilot, and how often an enemy appeared behind the player.
#include <cinttypes>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/json_text.h"
#include "cli/difficulty_args.h"
#include "core/io/file_io.h"
#include "core/io/output_path.h"
#include "core/paths.h"
#include "core/text/printable.h"
#include "game/assets/assets.h"
#include "game/difficulty/difficulty_probe.h"
#include "level/loader.h"

namespace bz::app {

namespace {

namespace fs = std::filesystem;

std::string seconds_cell(const game::ProbeSummary& s) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f (min %.1f, alive %d)", s.mean_first_death_s,
                  s.min_first_death_s, s.survived);
    return buf;
}

Json summary_json(const game::ProbeSummary& s) {
    return {{"games", s.games},
            {"mean_first_death_s", s.mean_first_death_s},
            {"min_first_death_s", s.min_first_death_s},
            {"alive_at_end", s.survived},
            {"spawns", s.spawns},
            {"rear_spawns", s.rear_spawns}};
}

int run(const DifficultyOptions& o) {
    if (!o.json.empty()) {
        // Before the first game: never the input level, a device, a folder or a foreign file.
        const std::vector<fs::path> inputs(o.levels.begin(), o.levels.end());
        check_output_file("--json", o.json, kJsonOutput, inputs, o.overwrite);
    }
    std::printf(
        "| level | difficulty | idle: first death, s | autopilot: first death, s | "
        "enemies behind |\n|---|---|---|---|---|\n");
    Json rows = Json::array();
    for (const std::string& file : o.levels) {
        level::LoadResult loaded = level::load_level_file(file);
        if (!loaded.ok()) {
            for (const level::Diagnostic& d : loaded.errors)
                std::fprintf(stderr, "%s\n", level::format(d).c_str());
            return 1;
        }
        const level::Level& lv = *loaded.level;
        const game::Assets assets(lv.backdrop);
        game::ProbeOptions po;
        po.max_seconds = o.seconds;
        for (const game::Difficulty d : o.difficulties) {
            const auto idle = game::probe_summary(lv, assets, d, game::Pilot::idle, o.seeds, 1, po);
            const auto pilot =
                game::probe_summary(lv, assets, d, game::Pilot::autopilot, o.seeds, 1, po);
            const int spawns = idle.spawns + pilot.spawns;
            const int rear = idle.rear_spawns + pilot.rear_spawns;
            const std::string name(game::difficulty_name(d));
            std::printf("| %s | %s | %s | %s | %d of %d (%.0f %%) |\n", lv.name.c_str(),
                        name.c_str(), seconds_cell(idle).c_str(), seconds_cell(pilot).c_str(), rear,
                        spawns, spawns ? 100.0 * rear / spawns : 0.0);
            std::fflush(stdout);
            rows.push_back({{"level", lv.name},
                            {"file", file},
                            {"difficulty", name},
                            {"idle", summary_json(idle)},
                            {"autopilot", summary_json(pilot)}});
        }
    }
    std::printf("\n%d games per cell (seeds 1..%d), %.0f s each at most.\n", o.seeds, o.seeds,
                o.seconds);
    if (!o.json.empty()) {
        const Json doc = {{"seeds", o.seeds}, {"max_seconds", o.seconds}, {"rows", rows}};
        write_file_atomic(o.json, json_text(doc));
    }
    return 0;
}

}  // namespace

int cmd_difficulty(Args args) {
    int exit_code = 0;
    const std::optional<DifficultyOptions> parsed =
        parse_command("difficulty", args, kDifficultyUsage, parse_difficulty_args, &exit_code);
    if (!parsed) return exit_code;
    return run(*parsed);
}

}  // namespace bz::app
