#include "core/paths.h"

#include <cstdlib>
#include <system_error>

namespace bz {

namespace {

namespace fs = std::filesystem;

struct Root {
    fs::path path;
    std::string origin;
};

fs::path executable_dir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}

bool has_shaders(const fs::path& root) {
    std::error_code ec;
    return !root.empty() && fs::is_directory(root / "shaders", ec);
}

// Same folder, whatever the spelling (symbolic links, "..").
bool same_folder(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return !a.empty() && fs::equivalent(a, b, ec);
}

Root find_root() {
    const fs::path exe_dir = executable_dir();
    const fs::path installed =
        exe_dir.empty() ? fs::path() : (exe_dir.parent_path() / "share" / "beamzone");
    if (has_shaders(installed)) return {installed, "installed"};
    if (const char* env = std::getenv("BEAMZONE_ROOT"); env && *env) return {env, "BEAMZONE_ROOT"};
    // Only a binary in its own build tree may reach back into the sources: an installed copy
    // must never depend on them.
    if (same_folder(exe_dir, BEAMZONE_BUILD_DIR)) return {BEAMZONE_SOURCE_DIR, "source tree"};
    return {installed.empty() ? fs::path(BEAMZONE_SOURCE_DIR) : installed, "missing"};
}

}  // namespace

std::filesystem::path project_root() {
    return find_root().path;
}
std::string project_root_origin() {
    return find_root().origin;
}
std::filesystem::path shaders_dir() {
    return project_root() / "shaders";
}
std::filesystem::path data_dir() {
    return project_root() / "data";
}
std::filesystem::path levels_dir() {
    return project_root() / "levels";
}

}  // namespace bz
