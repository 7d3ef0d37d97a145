#include "platform/gamepads.h"

#include <SDL.h>

#include "core/budgets.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/log.h"

namespace bz::platform {

int add_controller_mappings(const std::filesystem::path& file, std::string* error) {
    // Read through bz::read_file, never SDL's own open: a FIFO there would block SDL's
    // fopen forever and a huge file would be read whole.
    std::string text;
    try {
        text = read_file(file, budget::kGamepadDbBytes);
    } catch (const UserError& e) {
        if (error) *error = e.what();
        return -1;
    }
    if (text.empty()) return 0;  // SDL refuses a zero-sized buffer; no mappings is no error
    SDL_RWops* rw = SDL_RWFromConstMem(text.data(), static_cast<int>(text.size()));
    if (!rw) {
        if (error) *error = SDL_GetError();
        return -1;
    }
    const int n = SDL_GameControllerAddMappingsFromRW(rw, 1);  // 1: SDL closes rw
    if (n < 0 && error) *error = SDL_GetError();
    return n;
}

Gamepads::Gamepads(Log& log, const std::filesystem::path& bundled_db,
                   const std::filesystem::path& user_db)
    : log_(log) {
    if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) {
        log_.warn(std::string("game controllers unavailable: ") + SDL_GetError());
        return;
    }
    started_ = true;
    std::string error;
    const int bundled = add_controller_mappings(bundled_db, &error);
    if (bundled < 0) {
        log_.warn("cannot load controller mappings " + bundled_db.string() + ": " + error);
    } else {
        mappings_ += bundled;
    }
    std::error_code ec;
    if (std::filesystem::exists(user_db, ec)) {
        const int user = add_controller_mappings(user_db, &error);
        if (user < 0) {
            log_.warn("cannot load controller mappings " + user_db.string() + ": " + error);
        } else {
            mappings_ += user;
            log_.info("loaded " + std::to_string(user) + " controller mappings from " +
                      user_db.string());
        }
    }
    // Pads already plugged in arrive as SDL_CONTROLLERDEVICEADDED events on the first poll.
}

Gamepads::~Gamepads() {
    for (auto& [id, pad] : open_) SDL_GameControllerClose(pad);
    if (started_) SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
}

void Gamepads::handle_event(const SDL_Event& e) {
    if (!started_) return;
    if (e.type == SDL_CONTROLLERDEVICEADDED) {
        SDL_GameController* pad = SDL_GameControllerOpen(e.cdevice.which);  // a device index
        if (!pad) {
            log_.warn(std::string("cannot open game controller: ") + SDL_GetError());
            return;
        }
        const int id = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(pad));
        if (open_.count(id)) {
            SDL_GameControllerClose(pad);  // a duplicate add for a pad we already hold
            return;
        }
        open_[id] = pad;
        const char* name = SDL_GameControllerName(pad);
        log_.info(std::string("game controller connected: ") + (name ? name : "unnamed"));
    } else if (e.type == SDL_CONTROLLERDEVICEREMOVED) {
        const auto it = open_.find(e.cdevice.which);  // an instance id
        if (it == open_.end()) return;
        SDL_GameControllerClose(it->second);
        open_.erase(it);
        log_.info("game controller disconnected");
    }
}

}  // namespace bz::platform
