#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands/commands.h"
#include "core/error.h"
#include "core/text/printable.h"
#include "game/assets/level_models.h"
#include "game/assets/scene_budget.h"
#include "level/loader.h"

namespace bz::app {

namespace {

constexpr const char* kUsage =
    "usage: beamzone check [--quiet] FILE...\n"
    "Validates level files without opening a window, and imports every model a level names\n"
    "with the same importer and limits as play. Every problem is printed to stderr as\n"
    "'file:line:col: error: message'; a clean file prints one 'ok' line to stdout unless\n"
    "--quiet. Exit status: 0 all clean, 1 some file has errors, 2 usage error.\n";

// Imports each model the level names once, as play would; prints what fails. Returns the
// number of models that failed.
// number of models that failed, or 1 when the scene is over its budget (core/budgets.h).
int check_models(const level::Level& level) {
    int failed = 0;
    std::map<std::string, std::int64_t> triangles;
    for (const level::ObjectDesc& o : level.obstacles) {
        if (o.model.empty() || triangles.contains(o.model.string())) continue;
        try {
            triangles[o.model.string()] =
                static_cast<std::int64_t>(game::import_level_model(level, o).triangle_count());
        } catch (const UserError& e) {
            std::fprintf(stderr, "%s\n", printable_message(e.what()).c_str());
            triangles[o.model.string()] = 0;
            ++failed;
        }
    }
    if (failed > 0) return failed;
    try {
        game::check_scene_budget(level, triangles);
    } catch (const UserError& e) {
        std::fprintf(stderr, "%s\n", printable_message(e.what()).c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int cmd_check(Args args) {
    std::vector<std::string_view> files;
    bool quiet = false;
    bool options_done = false;
    for (const char* arg : args) {
        const std::string_view a = arg;
        if (!options_done && a == "--") {
            options_done = true;
        } else if (!options_done && (a == "--help" || a == "-h")) {
            std::fputs(kUsage, stdout);
            return 0;
        } else if (!options_done && (a == "--quiet" || a == "-q")) {
            quiet = true;
        } else if (!options_done && a.size() > 1 && a[0] == '-') {
            std::fprintf(stderr, "beamzone check: unknown option '%s'\n%s", printable(a).c_str(),
                         kUsage);
            return 2;
        } else {
            files.push_back(a);
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "beamzone check: no level files given\n%s", kUsage);
        return 2;
    }
    int failed = 0;
    for (const std::string_view file : files) {
        const level::LoadResult result = level::load_level_file(std::string(file));
        for (const auto& e : result.errors) std::fprintf(stderr, "%s\n", level::format(e).c_str());
        if (!result.ok() || check_models(*result.level) > 0) {
            ++failed;
        } else if (!quiet) {
            const auto& l = *result.level;
            std::printf("%s: ok: '%s', %zu obstacles, %zu camera keys\n", printable(file).c_str(),
                        printable(l.name).c_str(), l.obstacles.size(), l.camera_path.size());
        }
    }
    if (!quiet && files.size() > 1) {
        std::printf("checked %zu files: %zu clean, %d with errors\n", files.size(),
                    files.size() - static_cast<std::size_t>(failed), failed);
    }
    return failed == 0 ? 0 : 1;
}

}  // namespace bz::app
