#include "app/replay_level.h"

#include "core/paths.h"

namespace bz::app {

namespace fs = std::filesystem;

fs::path replay_level_path(const std::string& recorded, const fs::path& replay_file) {
    const fs::path p(recorded);
    std::error_code ec;
    if (p.is_absolute() || fs::exists(p, ec)) return p;
    for (const fs::path& base : {replay_file.parent_path(), project_root()}) {
        if (fs::exists(base / p, ec)) return base / p;
    }
    return p;
}

}  // namespace bz::app
