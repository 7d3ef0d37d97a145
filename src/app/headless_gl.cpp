#include "app/headless_gl.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "gl/gl.h"

namespace bz::app {

std::unique_ptr<platform::GlContext> make_headless_context() {
    setenv("SDL_VIDEODRIVER", "offscreen", 0);
    platform::ContextOptions o;
    o.mode = platform::WindowMode::hidden;
    o.width = 16;
    o.height = 16;
    return std::make_unique<platform::GlContext>(o);
}

void check_image_size(const platform::GlContext&, std::string_view option, int width, int height) {
    GLint texture = 0, renderbuffer = 0;
    GLint viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const int largest = std::min({texture, renderbuffer, viewport[0], viewport[1]});
    if (largest > 0 && std::max(width, height) > largest) {
        throw UserError(std::string(option) + " " + std::to_string(width) + "x" +
                        std::to_string(height) + ": this driver's largest picture is " +
                        std::to_string(largest) + " pixels a side");
    }
}

}  // namespace bz::app
