#pragma once
// Where beamzone keeps the user's files: SDL's per-user preference folder
// (~/.local/share/beamzone/beamzone on Linux), or BEAMZONE_PREF_DIR when set (tests use it so
// they never touch a real profile).
#include <filesystem>

namespace bz::platform {

struct PrefPaths {
    std::filesystem::path dir;
    std::filesystem::path settings;     // settings.toml
    std::filesystem::path high_scores;  // highscores.toml
    std::filesystem::path log;          // beamzone.log
    std::filesystem::path screenshots;  // screenshots/ (made on first use)
    std::filesystem::path gamepad_db;   // gamecontrollerdb.txt: user controller mappings
    std::filesystem::path levels;       // levels/: the player's own levels, offered in the menu
};

PrefPaths pref_paths_in(const std::filesystem::path& dir);
// Creates the folder if needed; throws UserError when there is no usable one.
PrefPaths pref_paths();

}  // namespace bz::platform
