#include "platform/pref_paths.h"

#include <SDL_error.h>
#include <SDL_filesystem.h>
#include <SDL_stdinc.h>

#include <cstdlib>
#include <string>

#include "core/error.h"

namespace bz::platform {

PrefPaths pref_paths_in(const std::filesystem::path& dir) {
    PrefPaths p;
    p.dir = dir;
    p.settings = dir / "settings.toml";
    p.high_scores = dir / "highscores.toml";
    p.log = dir / "beamzone.log";
    p.screenshots = dir / "screenshots";
    p.gamepad_db = dir / "gamecontrollerdb.txt";
    p.levels = dir / "levels";
    return p;
}

PrefPaths pref_paths() {
    if (const char* env = std::getenv("BEAMZONE_PREF_DIR"); env && *env) {
        std::error_code ec;
        std::filesystem::create_directories(env, ec);
        if (ec) {
            throw UserError(std::string("cannot create BEAMZONE_PREF_DIR ") + env + ": " +
                            ec.message());
        }
        return pref_paths_in(env);
    }
    char* sdl = SDL_GetPrefPath("beamzone", "beamzone");  // creates the folder
    if (!sdl) {
        throw UserError(std::string("no folder for settings (set BEAMZONE_PREF_DIR): ") +
                        SDL_GetError());
    }
    const std::filesystem::path dir(sdl);
    SDL_free(sdl);
    return pref_paths_in(dir);
}

}  // namespace bz::platform
