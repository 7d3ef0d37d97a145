#include "app/headless_gl.h"

#include <cstdlib>

namespace bz::app {

std::unique_ptr<platform::GlContext> make_headless_context() {
    setenv("SDL_VIDEODRIVER", "offscreen", 0);
    platform::ContextOptions o;
    o.mode = platform::WindowMode::hidden;
    o.width = 16;
    o.height = 16;
    return std::make_unique<platform::GlContext>(o);
}

}  // namespace bz::app
