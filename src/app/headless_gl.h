#pragma once
// A hidden GL context for the headless subcommands (render, reference checks, bench).
#include <memory>
#include <string_view>

#include "platform/gl_context.h"

namespace bz::app {

// Uses SDL's offscreen (EGL) driver unless SDL_VIDEODRIVER says otherwise.
std::unique_ptr<platform::GlContext> make_headless_context();

// Throws UserError when this driver cannot hold a `size` picture (its largest texture,
// renderbuffer or viewport is smaller): found before any work, not as an incomplete
// framebuffer at the end. `option` names the command-line option in the message.
void check_image_size(const platform::GlContext& context, std::string_view option, int width,
                      int height);

}  // namespace bz::app
