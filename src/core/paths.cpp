#include "core/paths.h"

#include <cstdlib>

namespace bz {

std::filesystem::path project_root() {
    if (const char* env = std::getenv("BEAMZONE_ROOT"); env && *env) return env;
    return BEAMZONE_SOURCE_DIR;
}
std::filesystem::path shaders_dir() { return project_root() / "shaders"; }
std::filesystem::path data_dir() { return project_root() / "data"; }
std::filesystem::path levels_dir() { return project_root() / "levels"; }

}  // namespace bz
