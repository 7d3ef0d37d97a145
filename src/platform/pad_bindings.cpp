#include "platform/pad_bindings.h"

#include <SDL_gamecontroller.h>

#include <cctype>
#include <utility>

#include "core/text/ascii_case.h"
#include "core/text/printable.h"

namespace bz::platform {

PadBindings default_pad_bindings() {
    PadBindings b;
    b[static_cast<std::size_t>(Action::fire)] = {SDL_CONTROLLER_BUTTON_A,
                                                 SDL_CONTROLLER_BUTTON_RIGHTSHOULDER};
    b[static_cast<std::size_t>(Action::pause)] = {SDL_CONTROLLER_BUTTON_START};
    b[static_cast<std::size_t>(Action::start)] = {SDL_CONTROLLER_BUTTON_START};
    b[static_cast<std::size_t>(Action::back)] = {SDL_CONTROLLER_BUTTON_B,
                                                 SDL_CONTROLLER_BUTTON_BACK};
    return b;
}

std::optional<int> parse_button(std::string_view text, std::string* error) {
    std::string lower(text);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // SDL's table, not a copy of it; it needs no SDL_Init.
    const SDL_GameControllerButton b = SDL_GameControllerGetButtonFromString(lower.c_str());
    if (b != SDL_CONTROLLER_BUTTON_INVALID) return static_cast<int>(b);
    if (error) {
        std::string names;
        for (int i = 0; i < SDL_CONTROLLER_BUTTON_MAX; ++i) {
            names += (i ? ", " : "") + button_name(i);
        }
        *error = "unknown button '" + printable(text) + "' (buttons: " + names + ")";
    }
    return std::nullopt;
}

std::string button_name(int button) {
    const char* name =
        SDL_GameControllerGetStringForButton(static_cast<SDL_GameControllerButton>(button));
    return name ? name : "button" + std::to_string(button);
}

std::string button_label(int button) {
    // The names printed on most pads, where SDL's differ from them.
    switch (button) {
        case SDL_CONTROLLER_BUTTON_LEFTSHOULDER:
            return "L1";
        case SDL_CONTROLLER_BUTTON_RIGHTSHOULDER:
            return "R1";
        case SDL_CONTROLLER_BUTTON_LEFTSTICK:
            return "L3";
        case SDL_CONTROLLER_BUTTON_RIGHTSTICK:
            return "R3";
        case SDL_CONTROLLER_BUTTON_DPAD_UP:
            return "D-PAD UP";
        case SDL_CONTROLLER_BUTTON_DPAD_DOWN:
            return "D-PAD DOWN";
        case SDL_CONTROLLER_BUTTON_DPAD_LEFT:
            return "D-PAD LEFT";
        case SDL_CONTROLLER_BUTTON_DPAD_RIGHT:
            return "D-PAD RIGHT";
        default:
            break;
    }
    std::string out = button_name(button);
    out = ascii_upper(std::move(out));
    return out;
}

std::string buttons_label(const PadBindings& b, Action a, std::size_t max_buttons) {
    const auto& buttons = b[static_cast<std::size_t>(a)];
    std::string out;
    for (std::size_t i = 0; i < buttons.size() && i < max_buttons; ++i) {
        if (i) out += ", ";
        out += button_label(buttons[i]);
    }
    return out;
}

}  // namespace bz::platform
