#pragma once
// What the current context runs on, for the choices that depend on it (timing method, line
// method). Needs a current context.
#include <string>

namespace bz::gl {

// GL_RENDERER, or "unknown".
std::string renderer_name();
// GL_VERSION (with the driver's own version), or "unknown".
std::string version_name();
// llvmpipe, softpipe or another software rasteriser: timer queries miss its vertex and
// geometry work, and its geometry shader runs on one thread.
bool is_software_renderer();

}  // namespace bz::gl
