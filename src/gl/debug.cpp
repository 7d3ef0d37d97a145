#include "gl/debug.h"

#include <cstdio>

namespace bz::gl {

namespace {

void GLAD_API_PTR callback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                           const GLchar* message, const void* user) {
    static_cast<DebugSink*>(const_cast<void*>(user))
        ->on_message(source, type, id, severity, message);
}

const char* type_name(GLenum type) {
    switch (type) {
        case GL_DEBUG_TYPE_ERROR:
            return "error";
        case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
            return "deprecated";
        case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
            return "undefined-behaviour";
        case GL_DEBUG_TYPE_PORTABILITY:
            return "portability";
        case GL_DEBUG_TYPE_PERFORMANCE:
            return "performance";
        default:
            return "other";
    }
}

}  // namespace

void DebugSink::install() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(callback, this);
    // Notifications are chatty (buffer placement hints); keep everything else.
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                          GL_FALSE);
}

void DebugSink::on_message(GLenum, GLenum type, GLuint id, GLenum severity, const char* text) {
    const bool is_error = type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR ||
                          severity == GL_DEBUG_SEVERITY_HIGH;
    if (is_error) ++errors_;
    std::string line =
        std::string("GL ") + type_name(type) + " #" + std::to_string(id) + ": " + text;
    if (echo_ && (is_error || severity != GL_DEBUG_SEVERITY_LOW)) {
        std::fprintf(stderr, "beamzone: %s\n", line.c_str());
    }
    std::vector<std::string>& kept =
        type == GL_DEBUG_TYPE_PERFORMANCE && !is_error ? hints_ : messages_;
    if (kept.size() < 256) kept.push_back(std::move(line));
}

}  // namespace bz::gl
