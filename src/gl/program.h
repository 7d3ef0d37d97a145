#pragma once
// A linked GLSL program built from one file per stage under shaders/.
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
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

    // Uniform setters by name; names the program does not use are ignored (GL returns -1).
    void set(const char* name, int v) const;
    void set(const char* name, unsigned v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::ivec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat4& v) const;
    void set_array(const char* name, const float* v, int count) const;

  private:
    GLint location(const char* name) const { return glGetUniformLocation(handle_.id(), name); }
    Handle<ProgramDeleter> handle_;
};

}  // namespace bz::gl
