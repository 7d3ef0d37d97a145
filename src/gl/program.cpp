#include "gl/program.h"

#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "gl/shader_source.h"

namespace bz::gl {

namespace {

struct ShaderDeleter {
    void operator()(GLuint id) const { glDeleteShader(id); }
};

std::string shader_log(GLuint shader) {
    GLint len = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(shader, len, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

std::string program_log(GLuint program) {
    GLint len = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program, len, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

}  // namespace

Program::Program(const std::vector<StageFile>& stages, const std::vector<std::string>& defines) {
    std::vector<Handle<ShaderDeleter>> shaders;
    std::string errors;
    for (const auto& stage : stages) {
        const ShaderSource src = assemble_shader(stage.file, defines);
        Handle<ShaderDeleter> shader(glCreateShader(stage.stage));
        const char* text = src.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) errors += map_info_log(shader_log(shader.id()), src.files);
        shaders.push_back(std::move(shader));
    }
    if (!errors.empty()) throw UserError("shader compile failed:\n" + errors);
    Handle<ProgramDeleter> program(glCreateProgram());
    for (const auto& s : shaders) glAttachShader(program.id(), s.id());
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    for (const auto& s : shaders) glDetachShader(program.id(), s.id());
    if (!ok) {
        std::string names;
        for (const auto& stage : stages) names += " " + stage.file.string();
        throw UserError("shader link failed for" + names + ":\n" + program_log(program.id()));
    }
    handle_ = std::move(program);
}

void Program::use() const {
    glUseProgram(handle_.id());
}
void Program::set(const char* n, int v) const {
    glProgramUniform1i(id(), location(n), v);
}
void Program::set(const char* n, unsigned v) const {
    glProgramUniform1ui(id(), location(n), v);
}
void Program::set(const char* n, float v) const {
    glProgramUniform1f(id(), location(n), v);
}
void Program::set(const char* n, const glm::vec2& v) const {
    glProgramUniform2fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec2& v) const {
    glProgramUniform2iv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
    glProgramUniform3fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
    glProgramUniform4fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
    glProgramUniformMatrix4fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set_array(const char* n, const float* v, int count) const {
    glProgramUniform1fv(id(), location(n), count, v);
}

}  // namespace bz::gl
