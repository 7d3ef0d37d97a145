#pragma once
// Gamepad buttons bound to player actions, rebindable like the keys. Buttons are SDL game
// controller buttons, named as SDL names them ("a", "b", "start", "rightshoulder", "dpup"), so
// the settings file reads the same on every pad SDL maps. The menus always answer to the
// d-pad, A, B and Start whatever is bound here, so no binding can lock a player out of them.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "platform/bindings.h"

namespace bz::platform {

using PadBindings = std::array<std::vector<int>, kActionCount>;  // SDL_GameControllerButton
// Fire on A and R1, pause and start on Start, back on B and Back: what the pad did before
// buttons could be rebound.
PadBindings default_pad_bindings();

// "a", "rightshoulder" (case-insensitive). Nothing, with the reason in *error, for an unknown
// name.
std::optional<int> parse_button(std::string_view text, std::string* error);
std::string button_name(int button);  // parse_button(button_name(b)) == b

// A button as the screen names it: "A", "R1", "D-PAD UP".
std::string button_label(int button);
// The buttons of an action for on-screen hints: "A, R1", or "" for none. At most
// `max_buttons` are named.
std::string buttons_label(const PadBindings& b, Action a, std::size_t max_buttons = 2);

}  // namespace bz::platform
