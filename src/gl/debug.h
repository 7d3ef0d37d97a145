#pragma once
// KHR_debug output. Every GL error is a bug: the sink counts errors so tests and the
// renderer's self-check can fail on them, and logs each message with its source and type.
// Performance hints (GL_DEBUG_TYPE_PERFORMANCE: a vendor driver saying a buffer moved to host
// memory or a shader was recompiled for some state) are kept apart: they are not wrong GL,
// and llvmpipe never sends them, so tests fail on every other message but only log these.
#include <string>
#include <vector>

#include "gl/gl.h"

namespace bz::gl {

class DebugSink {
  public:
    // Installs the callback on the current context (synchronous output, so the message
    // arrives inside the offending call and a debugger breaks at the right place).
    void install();
    int error_count() const { return errors_; }
    // Every message but the performance hints, as logged.
    const std::vector<std::string>& messages() const { return messages_; }
    const std::vector<std::string>& performance_hints() const { return hints_; }
    void clear() {
        errors_ = 0;
        messages_.clear();
        hints_.clear();
    }
    void set_echo(bool echo) { echo_ = echo; }

    void on_message(GLenum source, GLenum type, GLuint id, GLenum severity, const char* text);

  private:
    int errors_ = 0;
    bool echo_ = true;
    std::vector<std::string> messages_;
    std::vector<std::string> hints_;
};

}  // namespace bz::gl
