#include "platform/input.h"

#include <SDL_events.h>
#include <SDL_gamecontroller.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace bz::platform {

namespace {

static_assert(SDL_NUM_SCANCODES <= 512, "Input::keys_ is too small");
static_assert(SDL_CONTROLLER_BUTTON_MAX <= 32, "Input::Pad::buttons is too small");

// Below this a stick counts as centred: worn sticks rest a little off centre.
constexpr float kDeadZone = 0.2f;
constexpr float kTriggerFire = 0.5f;
constexpr float kStickPress = 0.5f;

// Radial dead zone, then rescaled so the output still reaches 1 at the rim.
void dead_zone(float& x, float& y) {
    const float r = std::sqrt(x * x + y * y);
    if (r < kDeadZone) {
        x = y = 0.0f;
        return;
    }
    const float k = std::min(1.0f, (r - kDeadZone) / (1.0f - kDeadZone)) / r;
    x *= k;
    y *= k;
}

float axis_value(Sint16 v) {
    return std::max(-1.0f, static_cast<float>(v) / 32767.0f);
}

}  // namespace

InputState pad_to_treads(const PadAxes& in, GamepadMode mode) {
    PadAxes a = in;
    dead_zone(a.left_x, a.left_y);
    dead_zone(a.right_x, a.right_y);
    InputState s;
    if (mode == GamepadMode::tank) {
        s.left_tread = -a.left_y;  // SDL's stick y grows toward the player
        s.right_tread = -a.right_y;
    } else {
        const float forward = -a.left_y;
        const float turn = a.left_x;  // right turns clockwise seen from above
        s.left_tread = std::clamp(forward + turn, -1.0f, 1.0f);
        s.right_tread = std::clamp(forward - turn, -1.0f, 1.0f);
    }
    s.fire = a.trigger_left > kTriggerFire || a.trigger_right > kTriggerFire;
    return s;
}

Input::Input(Bindings bindings, GamepadMode mode, PadBindings buttons)
    : bindings_(std::move(bindings)), mode_(mode), buttons_(std::move(buttons)) {}

bool Input::key_held(int scancode) const {
    return scancode >= 0 && scancode < static_cast<int>(keys_.size()) &&
           keys_[static_cast<std::size_t>(scancode)];
}

bool Input::action_held(Action a) const {
    for (const auto& k : bindings_[static_cast<std::size_t>(a)]) {
        if (key_held(k.scancode) && (k.mods & ~mods_) == 0) return true;
    }
    for (const int b : buttons_[static_cast<std::size_t>(a)]) {
        for (const auto& [id, pad] : pads_) {
            if (b >= 0 && b < static_cast<int>(pad.buttons.size()) &&
                pad.buttons[static_cast<std::size_t>(b)])
                return true;
        }
    }
    return false;
}

void Input::latch_action(Action a) {
    switch (a) {
        case Action::fire:
            latches_[latch_fire].pending = true;
            break;
        case Action::drive_forward:
            latches_[latch_up].pending = true;
            break;
        case Action::drive_back:
            latches_[latch_down].pending = true;
            break;
        case Action::turn_left:
            latches_[latch_left].pending = true;
            break;
        case Action::turn_right:
            latches_[latch_right].pending = true;
            break;
        default:
            break;
    }
}

void Input::key_down(int scancode, unsigned sdl_mod, bool repeat) {
    if (scancode >= 0 && scancode < static_cast<int>(keys_.size())) {
        keys_[static_cast<std::size_t>(scancode)] = true;
    }
    mods_ = modifiers_from_sdl(sdl_mod);
    // The most specific binding wins: Alt+Return toggles fullscreen without also doing what a
    // bare Return is bound to. Extra modifiers do not block a binding (fire is on Ctrl).
    int best = -1;
    std::vector<Action> matches;
    for (std::size_t i = 0; i < kActionCount; ++i) {
        const auto action = static_cast<Action>(i);
        for (const auto& k : bindings_[i]) {
            if (k.scancode != scancode || (k.mods & ~mods_) != 0) continue;
            const int specificity = __builtin_popcount(k.mods);
            if (specificity > best) {
                best = specificity;
                matches.clear();
            }
            if (specificity == best) matches.push_back(action);
            break;
        }
    }
    auto has = [&matches](Action a) {
        return std::find(matches.begin(), matches.end(), a) != matches.end();
    };
    // One menu key per press, confirm and back first: Return is both start and (say) a drive
    // key only if the player bound it so, and then confirming is what they meant.
    if (!repeat && (has(Action::start) || has(Action::fire))) {
        menu(MenuKey::confirm);
    } else if (!repeat && (has(Action::back) || has(Action::pause))) {
        menu(MenuKey::back);
    } else if (has(Action::drive_forward)) {
        menu(MenuKey::up);  // held arrows repeat in menus
    } else if (has(Action::drive_back)) {
        menu(MenuKey::down);
    } else if (has(Action::turn_left)) {
        menu(MenuKey::left);
    } else if (has(Action::turn_right)) {
        menu(MenuKey::right);
    }
    if (repeat) return;
    for (const Action a : matches) {
        if (is_held_action(a)) {
            latch_action(a);
        } else {
            pressed_.push_back(a);
        }
    }
}

void Input::key_up(int scancode, unsigned sdl_mod) {
    if (scancode >= 0 && scancode < static_cast<int>(keys_.size()))
        keys_[static_cast<std::size_t>(scancode)] = false;
    mods_ = modifiers_from_sdl(sdl_mod);
    if (capturing_ && scancode == capture_modifier_) {
        captured_ = KeyBinding{scancode, kModNone};
        capturing_ = false;
        capture_modifier_ = -1;
    }
}

namespace {

bool is_modifier_key(int scancode) {
    return scancode >= SDL_SCANCODE_LCTRL && scancode <= SDL_SCANCODE_RGUI;
}

}  // namespace

void Input::capture_key_down(int scancode, unsigned sdl_mod) {
    if (scancode >= 0 && scancode < static_cast<int>(keys_.size())) {
        keys_[static_cast<std::size_t>(scancode)] = true;
    }
    mods_ = modifiers_from_sdl(sdl_mod);
    if (scancode == SDL_SCANCODE_ESCAPE) {
        captured_ = kCaptureCancelled;
        capturing_ = false;
    } else if (is_modifier_key(scancode)) {
        capture_modifier_ = scancode;  // bound alone if released with nothing else
    } else if (scancode > SDL_SCANCODE_UNKNOWN && scancode < SDL_NUM_SCANCODES) {
        captured_ = KeyBinding{scancode, mods_};
        capturing_ = false;
        capture_modifier_ = -1;
    }
}

void Input::begin_capture() {
    capturing_ = true;
    capture_modifier_ = -1;
    captured_.reset();
    captured_button_.reset();
}

std::optional<KeyBinding> Input::take_captured() {
    return std::exchange(captured_, std::nullopt);
}

std::optional<int> Input::take_captured_button() {
    return std::exchange(captured_button_, std::nullopt);
}

void Input::pad_button(const SDL_Event& e) {
    const bool down = e.type == SDL_CONTROLLERBUTTONDOWN;
    const int button = e.cbutton.button;
    if (button < 32) pads_[e.cbutton.which].buttons[static_cast<std::size_t>(button)] = down;
    if (!down) return;
    if (capturing_) {  // the keys page binds this button; it does nothing else now
        captured_button_ = button;
        capturing_ = false;
        return;
    }
    // The menus answer to the same buttons whatever is bound, so no binding locks them.
    switch (button) {
        case SDL_CONTROLLER_BUTTON_START:
        case SDL_CONTROLLER_BUTTON_A:
            menu(MenuKey::confirm);
            break;
        case SDL_CONTROLLER_BUTTON_B:
        case SDL_CONTROLLER_BUTTON_BACK:
            menu(MenuKey::back);
            break;
        case SDL_CONTROLLER_BUTTON_DPAD_UP:
            latches_[latch_up].pending = true;
            menu(MenuKey::up);
            break;
        case SDL_CONTROLLER_BUTTON_DPAD_DOWN:
            latches_[latch_down].pending = true;
            menu(MenuKey::down);
            break;
        case SDL_CONTROLLER_BUTTON_DPAD_LEFT:
            latches_[latch_left].pending = true;
            menu(MenuKey::left);
            break;
        case SDL_CONTROLLER_BUTTON_DPAD_RIGHT:
            latches_[latch_right].pending = true;
            menu(MenuKey::right);
            break;
        default:
            break;
    }
    // The game's actions follow the bindings: a held action is latched so a tap within one
    // tick still counts; a pressed one is queued once.
    for (std::size_t i = 0; i < kActionCount; ++i) {
        const auto& bound = buttons_[i];
        if (std::find(bound.begin(), bound.end(), button) == bound.end()) continue;
        const auto a = static_cast<Action>(i);
        if (is_held_action(a))
            latch_action(a);
        else
            pressed_.push_back(a);
    }
}

void Input::pad_axis(const SDL_Event& e) {
    PadAxes& a = pads_[e.caxis.which].axes;
    const float v = axis_value(e.caxis.value);
    // A stick pushed past half way is a press for the menus; a trigger pulled past its fire
    // point is a shot, latched like a button so a quick pull is never lost.
    auto crossed = [v](float before, float threshold) {
        return (v > threshold && before <= threshold) || (v < -threshold && before >= -threshold);
    };
    switch (e.caxis.axis) {
        case SDL_CONTROLLER_AXIS_LEFTX:
            if (crossed(a.left_x, kStickPress)) menu(v > 0 ? MenuKey::right : MenuKey::left);
            a.left_x = v;
            break;
        case SDL_CONTROLLER_AXIS_LEFTY:
            if (crossed(a.left_y, kStickPress)) {
                const bool is_up = v < 0;  // SDL's y grows toward the player
                latches_[is_up ? latch_up : latch_down].pending = true;
                menu(is_up ? MenuKey::up : MenuKey::down);
            }
            a.left_y = v;
            break;
        case SDL_CONTROLLER_AXIS_RIGHTX:
            a.right_x = v;
            break;
        case SDL_CONTROLLER_AXIS_RIGHTY:
            a.right_y = v;
            break;
        case SDL_CONTROLLER_AXIS_TRIGGERLEFT:
        case SDL_CONTROLLER_AXIS_TRIGGERRIGHT: {
            float& t =
                e.caxis.axis == SDL_CONTROLLER_AXIS_TRIGGERLEFT ? a.trigger_left : a.trigger_right;
            const float next = std::max(0.0f, v);
            if (next > kTriggerFire && t <= kTriggerFire) latches_[latch_fire].pending = true;
            t = next;
            break;
        }
        default:
            break;
    }
}

void Input::handle_event(const SDL_Event& e) {
    switch (e.type) {
        case SDL_KEYDOWN: {
            const int sc = static_cast<int>(e.key.keysym.scancode);
            if (capturing_ && e.key.repeat == 0) {
                capture_key_down(sc, e.key.keysym.mod);
            } else if (!capturing_) {
                key_down(sc, e.key.keysym.mod, e.key.repeat != 0);
            }
            break;
        }
        case SDL_KEYUP:
            key_up(static_cast<int>(e.key.keysym.scancode), e.key.keysym.mod);
            break;
        case SDL_CONTROLLERAXISMOTION:
            pad_axis(e);
            break;
        case SDL_CONTROLLERBUTTONDOWN:
        case SDL_CONTROLLERBUTTONUP:
            pad_button(e);
            break;
        case SDL_CONTROLLERDEVICEREMOVED:
            pads_.erase(e.cdevice.which);
            break;
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_FOCUS_LOST) release_all();
            break;
        default:
            break;
    }
}

InputState Input::state() const {
    auto held = [this](Action a) { return action_held(a) ? 1.0f : 0.0f; };
    const float drive = held(Action::drive_forward) - held(Action::drive_back);
    const float turn = held(Action::turn_right) - held(Action::turn_left);
    float left = held(Action::left_tread_forward) - held(Action::left_tread_back) + drive + turn;
    float right = held(Action::right_tread_forward) - held(Action::right_tread_back) + drive - turn;
    bool fire = action_held(Action::fire);
    InputState out;
    out.up = action_held(Action::drive_forward);
    out.down = action_held(Action::drive_back);
    out.left = action_held(Action::turn_left);
    out.right = action_held(Action::turn_right);
    for (const auto& [id, pad] : pads_) {
        out.up = out.up || pad.buttons[SDL_CONTROLLER_BUTTON_DPAD_UP];
        out.down = out.down || pad.buttons[SDL_CONTROLLER_BUTTON_DPAD_DOWN];
        out.left = out.left || pad.buttons[SDL_CONTROLLER_BUTTON_DPAD_LEFT];
        out.right = out.right || pad.buttons[SDL_CONTROLLER_BUTTON_DPAD_RIGHT];
        const InputState p = pad_to_treads(pad.axes, mode_);
        left += p.left_tread;
        right += p.right_tread;
        fire = fire || p.fire;  // the triggers; fire's buttons count in action_held
    }
    out.left_tread = std::clamp(left, -1.0f, 1.0f);
    out.right_tread = std::clamp(right, -1.0f, 1.0f);
    out.fire = fire;
    return out;
}

InputState Input::next_tick() {
    InputState s = state();
    bool* fields[latched_count] = {&s.fire, &s.up, &s.down, &s.left, &s.right};
    for (std::size_t i = 0; i < latches_.size(); ++i) {
        Latch& l = latches_[i];
        bool& value = *fields[i];
        if (l.pending) {
            if (l.sent) {
                value = false;  // released and pressed again: show the release first
            } else {
                value = true;
                l.pending = false;
            }
        }
        l.sent = value;
    }
    return s;
}

std::vector<MenuKey> Input::take_menu_keys() {
    std::vector<MenuKey> out;
    out.swap(menu_keys_);
    return out;
}

std::vector<Action> Input::take_pressed() {
    std::vector<Action> out;
    out.swap(pressed_);
    return out;
}

void Input::release_all() {
    keys_.fill(false);
    for (Latch& l : latches_) l.pending = false;
    mods_ = kModNone;
    for (auto& [id, pad] : pads_) {
        pad.buttons.fill(false);
        pad.axes = {};
    }
}

}  // namespace bz::platform
