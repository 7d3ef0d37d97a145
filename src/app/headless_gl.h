#pragma once
// A hidden GL context for the headless subcommands (render, reference checks, bench).
#include <memory>

#include "platform/gl_context.h"

namespace bz::app {

// Uses SDL's offscreen (EGL) driver unless SDL_VIDEODRIVER says otherwise.
std::unique_ptr<platform::GlContext> make_headless_context();

}  // namespace bz::app
