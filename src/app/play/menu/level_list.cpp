#include "app/play/menu/level_list.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <tuple>

#include "core/text/ascii_case.h"
#include "core/text/printable.h"
#include "level/loader.h"

namespace bz::app::menu {

namespace {

struct Found {
    LevelChoice choice;
    int order = level::kDefaultMenuOrder;
};

Found describe(const std::filesystem::path& file, bool user) {
    Found f;
    f.choice.file = file;
    f.choice.user = user;
    const level::LoadResult r = level::load_level_file(file);
    if (!r.level) {
        std::string name = file.stem().string();
        std::replace(name.begin(), name.end(), '_', ' ');
        f.choice.name = ascii_upper(menu_label(name));
        f.choice.description = "DOES NOT LOAD: CHOOSE IT TO SEE WHY";
        f.choice.loads = false;
        return f;
    }
    f.choice.name = ascii_upper(menu_label(r.level->name));
    f.choice.description =
        ascii_upper(menu_label(r.level->description, 3 * budget::kMenuLabelChars));
    f.choice.listed = r.level->listed;
    f.order = r.level->menu_order;
    return f;
}

}  // namespace

std::vector<LevelChoice> find_levels(const std::filesystem::path& shipped,
                                     const std::filesystem::path& user) {
    std::vector<LevelChoice> out;
    for (const auto& [dir, mine] : {std::pair{shipped, false}, std::pair{user, true}}) {
        std::error_code ec;
        std::vector<Found> found;
        for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
            if (e.path().extension() != ".toml") continue;
            Found f = describe(e.path(), mine);
            if (f.choice.listed) found.push_back(std::move(f));
        }
        std::sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
            return std::tie(a.order, a.choice.name, a.choice.file) <
                   std::tie(b.order, b.choice.name, b.choice.file);
        });
        for (Found& f : found) out.push_back(std::move(f.choice));
    }
    return out;
}

}  // namespace bz::app::menu
