#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands/commands.h"
#include "app/commands/parse_command.h"
#include "cli/check_args.h"
#include "core/error.h"
#include "core/text/printable.h"
#include "game/assets/level_models.h"
#include "game/assets/scene_budget.h"
#include "level/loader.h"

namespace bz::app {

namespace {

// Imports each model the level names once, as play would; prints what fails. Returns the
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
    int exit_code = 0;
    const std::optional<CheckOptions> parsed =
        parse_command("check", args, kCheckUsage, parse_check_args, &exit_code);
    if (!parsed) return exit_code;
    const auto& [files, quiet] = *parsed;
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
