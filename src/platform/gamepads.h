#pragma once
// Opens game controllers as they are plugged in and closes them when pulled. Mappings come
// from the bundled community database, then from a user file that may override it.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

union SDL_Event;
struct _SDL_GameController;

namespace bz {
class Log;
}

namespace bz::platform {

class Gamepads {
  public:
    // Starts SDL's game-controller subsystem (a failure is logged; there are then no pads).
    // `user_db` is loaded after `bundled_db` when it exists, so its lines win.
    Gamepads(Log& log, const std::filesystem::path& bundled_db,
             const std::filesystem::path& user_db);
    ~Gamepads();
    Gamepads(const Gamepads&) = delete;
    Gamepads& operator=(const Gamepads&) = delete;

    // Handles SDL_CONTROLLERDEVICEADDED / REMOVED; other events are ignored.
    void handle_event(const SDL_Event& event);
    std::size_t count() const { return open_.size(); }
    int mappings_loaded() const { return mappings_; }

  private:
    Log& log_;
    bool started_ = false;
    int mappings_ = 0;
    std::map<int, _SDL_GameController*> open_;  // by joystick instance id
};

// Adds the mappings in `file` to SDL; returns how many, or -1 with the reason in *error.
int add_controller_mappings(const std::filesystem::path& file, std::string* error);

}  // namespace bz::platform
