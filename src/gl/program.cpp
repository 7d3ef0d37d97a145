#include "gl/program.h"

#include <algorithm>
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
    std::vector<std::string> declared;
    for (const auto& stage : stages) {
        label_ += (label_.empty() ? "" : " + ") + stage.file.filename().string();
        const ShaderSource src = assemble_shader(stage.file, defines);
        const auto names = declared_uniforms(src.text);
        declared.insert(declared.end(), names.begin(), names.end());
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
    read_uniforms(declared);
}

// The active default-block uniforms and their locations, once: a set then costs a search of a
// short sorted table instead of glGetUniformLocation's parse of the name in the driver.
void Program::read_uniforms(const std::vector<std::string>& declared) {
    const GLuint p = handle_.id();
    GLint count = 0;
    glGetProgramInterfaceiv(p, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLenum props[] = {GL_NAME_LENGTH, GL_LOCATION, GL_BLOCK_INDEX};
        GLint values[3] = {0, -1, -1};
        glGetProgramResourceiv(p, GL_UNIFORM, static_cast<GLuint>(i), 3, props, 3, nullptr, values);
        if (values[2] != -1 || values[1] < 0) continue;  // in a block: no location of its own
        std::string name(static_cast<std::size_t>(std::max(values[0], 1)), '\0');
        glGetProgramResourceName(p, GL_UNIFORM, static_cast<GLuint>(i), values[0], nullptr,
                                 name.data());
        name.resize(std::char_traits<char>::length(name.c_str()));
        // GL names an array by its first element; its base name's location is the same.
        if (name.size() > 3 && name.ends_with("[0]")) name.resize(name.size() - 3);
        uniforms_.push_back({std::move(name), values[1]});
    }
    for (const auto& d : declared) uniforms_.push_back({d, -1});
    // Active entries first for each name, so the dedup keeps the location.
    std::stable_sort(uniforms_.begin(), uniforms_.end(),
                     [](const Uniform& a, const Uniform& b) { return a.name < b.name; });
    uniforms_.erase(
        std::unique(uniforms_.begin(), uniforms_.end(),
                    [](const Uniform& a, const Uniform& b) { return a.name == b.name; }),
        uniforms_.end());
}

bool Program::declares(std::string_view name) const {
    const auto it = std::lower_bound(
        uniforms_.begin(), uniforms_.end(), name,
        [](const Uniform& u, std::string_view n) { return std::string_view(u.name) < n; });
    return it != uniforms_.end() && it->name == name;
}

GLint Program::location(std::string_view name) const {
    const auto it = std::lower_bound(
        uniforms_.begin(), uniforms_.end(), name,
        [](const Uniform& u, std::string_view n) { return std::string_view(u.name) < n; });
    if (it != uniforms_.end() && it->name == name) return it->location;
    report_unknown(name);
    return -1;
}

void Program::report_unknown(std::string_view name) const {
    if (std::find(reported_.begin(), reported_.end(), name) != reported_.end()) return;
    reported_.emplace_back(name);
    const std::string message = "uniform '" + std::string(name) + "' is not declared by " +
                                (label_.empty() ? std::string("an empty program") : label_);
    glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 1,
                         GL_DEBUG_SEVERITY_HIGH, static_cast<GLsizei>(message.size()),
                         message.c_str());
}

void Program::use() const {
    glUseProgram(handle_.id());
}
void Program::set(const char* n, int v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1i(id(), at, v);
}
void Program::set(const char* n, unsigned v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1ui(id(), at, v);
}
void Program::set(const char* n, float v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1f(id(), at, v);
}
void Program::set(const char* n, const glm::vec2& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform2fv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec2& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform2iv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec4& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform4iv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform3fv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform4fv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
    if (const GLint at = location(n); at >= 0)
        glProgramUniformMatrix4fv(id(), at, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::set_array(const char* n, const float* v, int count) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1fv(id(), at, count, v);
}

void Program::set_array(const char* n, const int* v, int count) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1iv(id(), at, count, v);
}

void Program::set_array(const char* n, const glm::ivec2* v, int count) const {
    if (const GLint at = location(n); at >= 0)
        glProgramUniform2iv(id(), at, count, glm::value_ptr(v[0]));
}

}  // namespace bz::gl
