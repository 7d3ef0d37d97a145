#pragma once
// Where beamzone keeps the user's files: SDL's per-user preference folder
// (~/.local/share/beamzone/beamzone on Linux), or BEAMZONE_PREF_DIR when set (tests use it so
// they never touch a real profile). What it measures about the machine (line-methods.json) is
// a cache, safe to lose: it goes to the cache folder ($XDG_CACHE_HOME/beamzone, else
// ~/.cache/beamzone), or BEAMZONE_CACHE_DIR when set; under BEAMZONE_PREF_DIR alone it stays in
// that folder, so a test's fresh folder is as fresh as before.
#include <filesystem>

namespace bz::platform {

struct PrefPaths {
    std::filesystem::path dir;
    std::filesystem::path settings;      // settings.toml
    std::filesystem::path high_scores;   // highscores.toml
    std::filesystem::path log;           // beamzone.log
    std::filesystem::path screenshots;   // screenshots/ (made on first use)
    std::filesystem::path gamepad_db;    // gamecontrollerdb.txt: user controller mappings
    std::filesystem::path levels;        // levels/: the player's own levels, offered in the menu
    std::filesystem::path line_methods;  // line-methods.json, in the cache folder
};

// Every file in `dir` (the cache too).
PrefPaths pref_paths_in(const std::filesystem::path& dir);
// Creates the folder if needed; throws UserError when there is no usable one.
PrefPaths pref_paths();

}  // namespace bz::platform
