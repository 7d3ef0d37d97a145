#pragma once
// A linked GLSL program built from one file per stage under shaders/.
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "gl/handle.h"

namespace bz::gl {

struct ProgramDeleter {
    void operator()(GLuint id) const { glDeleteProgram(id); }
};

struct StageFile {
    GLenum stage;  // GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER
    std::filesystem::path file;
};

class Program {
  public:
    Program() = default;
    // Throws UserError whose message names file:line:col for every compile or link error.
    Program(const std::vector<StageFile>& stages, const std::vector<std::string>& defines = {});

    void use() const;
    GLuint id() const { return handle_.id(); }
    explicit operator bool() const { return static_cast<bool>(handle_); }

    // Uniform setters by name, through the table of locations read once at link. A name the
    // program's source declares but the compiler dropped (inactive in this variant, or
    // optimised away) is skipped, as GL skips location -1. A name its source does not declare
    // at all is a bug in the caller (a misspelling, a uniform renamed or removed): it is
    // reported as a GL_DEBUG_TYPE_ERROR through KHR_debug, once per program and name, so
    // tests, `render`, `bench` and `play` fail on it like on any GL error (gl/debug.h).
    void set(const char* name, int v) const;
    void set(const char* name, unsigned v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::ivec2& v) const;
    void set(const char* name, const glm::ivec4& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat4& v) const;
    void set_array(const char* name, const float* v, int count) const;
    void set_array(const char* name, const int* v, int count) const;
    void set_array(const char* name, const glm::ivec2* v, int count) const;

    // The location of `name`: -1 when declared but inactive, or when unknown (then reported).
    GLint location(std::string_view name) const;
    // True when the source declares `name` (active or not).
    bool declares(std::string_view name) const;

  private:
    struct Uniform {
        std::string name;  // an array by its base name ("u_weights", not "u_weights[0]")
        GLint location;    // -1: declared in the source, inactive in the program
    };
    void read_uniforms(const std::vector<std::string>& declared);
    void report_unknown(std::string_view name) const;

    Handle<ProgramDeleter> handle_;
    std::string label_;                          // the stage files, for messages
    std::vector<Uniform> uniforms_;              // sorted by name
    mutable std::vector<std::string> reported_;  // unknown names already reported
};

}  // namespace bz::gl
