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
    p.line_methods = dir / "line-methods.json";
    return p;
}

namespace {

std::string env_or_empty(const char* name) {
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
}

// The cache folder, or `fallback` when the environment names none. Not created here: a
// cache that cannot be written is reported where it is written, and the game goes on.
std::filesystem::path cache_dir(const std::filesystem::path& fallback, bool pref_from_env) {
    if (std::string d = env_or_empty("BEAMZONE_CACHE_DIR"); !d.empty()) return d;
    if (pref_from_env) return fallback;
    // XDG: a relative XDG_CACHE_HOME is invalid and ignored.
    if (std::string d = env_or_empty("XDG_CACHE_HOME"); !d.empty() && d.front() == '/')
        return std::filesystem::path(d) / "beamzone";
    if (std::string h = env_or_empty("HOME"); !h.empty() && h.front() == '/')
        return std::filesystem::path(h) / ".cache" / "beamzone";
    return fallback;
}

PrefPaths with_cache(PrefPaths p, bool pref_from_env) {
    const std::filesystem::path cache = cache_dir(p.dir, pref_from_env);
    p.line_methods = cache / "line-methods.json";
    return p;
}

}  // namespace

PrefPaths pref_paths() {
    if (const char* env = std::getenv("BEAMZONE_PREF_DIR"); env && *env) {
        std::error_code ec;
        std::filesystem::create_directories(env, ec);
        if (ec) {
            throw UserError(std::string("cannot create BEAMZONE_PREF_DIR ") + env + ": " +
                            ec.message());
        }
        return with_cache(pref_paths_in(env), true);
    }
    char* sdl = SDL_GetPrefPath("beamzone", "beamzone");  // creates the folder
    if (!sdl) {
        throw UserError(std::string("no folder for settings (set BEAMZONE_PREF_DIR): ") +
                        SDL_GetError());
    }
    const std::filesystem::path dir(sdl);
    SDL_free(sdl);
    return with_cache(pref_paths_in(dir), false);
}

}  // namespace bz::platform
