#include <cstdio>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "app/commands/commands.h"
#include "core/error.h"
#include "game/assets/level_models.h"
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
int check_models(const level::Level& level) {
    int failed = 0;
    std::set<std::string> seen;
    for (const level::ObjectDesc& o : level.obstacles) {
        if (o.model.empty() || !seen.insert(o.model.string()).second) continue;
        try {
            game::import_level_model(level, o);
        } catch (const UserError& e) {
            std::fprintf(stderr, "%s\n", e.what());
            ++failed;
        }
    }
    return failed;
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
            std::fprintf(stderr, "beamzone check: unknown option '%s'\n%s", arg, kUsage);
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
            std::printf("%.*s: ok: '%s', %zu obstacles, %zu camera keys\n",
                        static_cast<int>(file.size()), file.data(), l.name.c_str(),
                        l.obstacles.size(), l.camera_path.size());
        }
    }
    if (!quiet && files.size() > 1) {
        std::printf("checked %zu files: %zu clean, %d with errors\n", files.size(),
                    files.size() - static_cast<std::size_t>(failed), failed);
    }
    return failed == 0 ? 0 : 1;
}

}  // namespace bz::app
