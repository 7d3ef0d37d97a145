// `beamzone difficulty`: the difficulty table. For each level and difficulty, 20 (--seeds)
// headless games from the first tick: the time to the first death for an idle player and for
// the autopilot, and how often an enemy appeared behind the player.
#include <cinttypes>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands/cli_args.h"
#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "app/json_text.h"
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

constexpr const char* kUsage =
    "usage: beamzone difficulty [LEVEL...] [--seeds N] [--seconds S]\n"
    "                           [--difficulty easy|normal|arcade] [--json FILE] [--overwrite]\n"
    "Plays N games (default 20, seeds 1..N) per level and difficulty headless and prints, as a\n"
    "Markdown table, the mean time to the first death of an idle player and of the autopilot\n"
    "(games still alive after S seconds, default 120, count as S; 'alive' says how many), and\n"
    "the share of enemies that appeared in the 90 degrees behind the player. Without LEVEL,\n"
    "every shipped level that has enemies. --json writes the same numbers as JSON (an existing\n"
    "file there must be JSON unless --overwrite is given).\n";

struct Options {
    std::vector<std::string> levels;
    int seeds = 20;
    double seconds = 120.0;
    std::vector<game::Difficulty> difficulties{game::Difficulty::easy, game::Difficulty::normal,
                                               game::Difficulty::arcade};
    std::string json;
    bool overwrite = false;  // --json may replace an existing file that is not JSON
};

Options parse(Args args) {
    Options o;
    ArgCursor cur(static_cast<int>(args.size()), args.data());
    bool difficulty_given = false;
    while (!cur.done()) {
        const std::string_view a = cur.next();
        if (a == "--seeds") {
            o.seeds = parse_int(a, cur.value(a), 1, 10000);
        } else if (a == "--seconds") {
            o.seconds = parse_number(a, cur.value(a));
            if (!(o.seconds > 0.0 && o.seconds <= 3600.0))
                throw UsageError("--seconds must be more than 0 and at most 3600");
        } else if (a == "--difficulty") {
            const std::string_view v = cur.value(a);
            const auto d = game::parse_difficulty(v);
            if (!d) {
                throw UsageError("--difficulty must be one of " +
                                 std::string(game::kDifficultyNames) + ", not '" + printable(v) +
                                 "'");
            }
            if (!difficulty_given) o.difficulties.clear();
            difficulty_given = true;
            o.difficulties.push_back(*d);
        } else if (a == "--json") {
            o.json = cur.value(a);
        } else if (a == "--overwrite") {
            o.overwrite = true;
        } else if (!a.empty() && a[0] == '-') {
            throw UsageError("unknown option " + printable(a));
        } else {
            o.levels.emplace_back(a);
        }
    }
    if (o.levels.empty()) {
        for (const char* name : {"tutorial", "classic", "maze", "volcano_night", "plains"})
            o.levels.push_back((levels_dir() / (std::string(name) + ".toml")).string());
    }
    return o;
}

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

int run(const Options& o) {
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
    const std::optional<Options> parsed =
        parse_command("difficulty", args, kUsage, parse, &exit_code);
    if (!parsed) return exit_code;
    return run(*parsed);
}

}  // namespace bz::app
