#include "gl/driver.h"

#include "gl/gl.h"

namespace bz::gl {

std::string renderer_name() {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return r ? r : "unknown";
}

std::string version_name() {
    const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return v ? v : "unknown";
}

bool is_software_renderer() {
    const std::string r = renderer_name();
    return r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos ||
           r.find("Software") != std::string::npos;
}

}  // namespace bz::gl
