#pragma once
// Shader text assembly, kept free of GL so it can be unit-tested: resolves #include "file"
// (relative to the including file), injects #defines after #version, and records which file
// each GLSL source-string number stands for, so compiler messages can name file:line.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bz::gl {

struct ShaderSource {
    std::string text;
    std::vector<std::string> files;  // index = GLSL source-string number used in #line
};

// Throws UserError for a missing file, an include cycle, or a file with no #version line.
ShaderSource assemble_shader(const std::filesystem::path& file,
                             const std::vector<std::string>& defines = {});

// Rewrites a GLSL info log so each "N:L(C): msg" (Mesa) or "N(L) : msg" (NVIDIA) line starts
// with "file:L:C: msg" using the file table of the assembled source.
std::string map_info_log(std::string_view log, const std::vector<std::string>& files);

// The names of the default-block uniforms an assembled source declares (`uniform T name;`,
// `uniform T a, b[4];`, with any layout or precision qualifiers), comments skipped. Uniform
// blocks (`uniform Name { ... }`) are not default-block uniforms and are left out. Declarations
// inside a branch the preprocessor drops count too: the program's interface is what its source
// text declares, of which the compiled variant and the optimiser keep a subset (gl::Program).
std::vector<std::string> declared_uniforms(std::string_view glsl);

}  // namespace bz::gl
