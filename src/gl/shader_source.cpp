#include "gl/shader_source.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "core/budgets.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/text/printable.h"

namespace bz::gl {
namespace fs = std::filesystem;

namespace {

bool starts_with_directive(std::string_view line, std::string_view directive) {
    std::size_t i = 0;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i >= line.size() || line[i] != '#') return false;
    ++i;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    return line.substr(i, directive.size()) == directive;
}

// The one name of a file however it is spelt ("./x.glsl", "a/../x.glsl", a link to it): cycles
// and repeats are found by this, not by the spelling.
fs::path resolved(const fs::path& file) {
    std::error_code ec;
    fs::path r = fs::weakly_canonical(fs::absolute(file, ec), ec);
    return ec ? file.lexically_normal() : r;
}

struct Assembler {
    std::vector<std::string> files;
    std::vector<fs::path> stack;  // resolved paths of the files being pasted, root first
    std::vector<fs::path> done;   // resolved paths already pasted: a diamond pastes once
    std::ostringstream out;
    std::size_t bytes = 0;  // text read so far, against budget::kShaderAssembledBytes

    void append(const fs::path& file, bool is_root, const std::vector<std::string>& defines) {
        const fs::path id = resolved(file);
        if (std::find(stack.begin(), stack.end(), id) != stack.end()) {
            throw UserError(printable(file.string()) + ": include cycle (the file includes " +
                            "itself through " + std::to_string(stack.size()) + " level(s))");
        }
        // Included once per program, like #pragma once: two includes of one file along two
        // paths would only redefine its functions, and pasting each would grow exponentially.
        if (!is_root && std::find(done.begin(), done.end(), id) != done.end()) return;
        if (static_cast<int>(stack.size()) >= budget::kShaderIncludeDepth) {
            throw UserError(printable(file.string()) + ": includes nested more than " +
                            std::to_string(budget::kShaderIncludeDepth) + " deep");
        }
        const std::string text = read_file(file, budget::kShaderFileBytes);
        bytes += text.size();
        if (bytes > budget::kShaderAssembledBytes) {
            throw UserError(printable(file.string()) + ": the program's assembled source passes " +
                            std::to_string(budget::kShaderAssembledBytes) + " bytes");
        }
        done.push_back(id);
        const int index = static_cast<int>(files.size());
        files.push_back(file.string());
        stack.push_back(id);
        if (!is_root) out << "#line 1 " << index << '\n';
        std::istringstream in(text);
        std::string line;
        int number = 0;
        bool saw_version = false;
        while (std::getline(in, line)) {
            ++number;
            if (starts_with_directive(line, "version")) {
                if (!is_root) continue;  // only the root file names the version
                saw_version = true;
                out << line << '\n';
                for (const auto& d : defines) out << "#define " << d << '\n';
                out << "#line " << number + 1 << ' ' << index << '\n';
                continue;
            }
            if (starts_with_directive(line, "include")) {
                const auto open = line.find('"');
                const auto close = line.rfind('"');
                if (open == std::string::npos || close <= open) {
                    throw UserError(file.string() + ":" + std::to_string(number) +
                                    ":1: error: malformed #include");
                }
                const fs::path inc = file.parent_path() / line.substr(open + 1, close - open - 1);
                append(inc, false, defines);
                out << "#line " << number + 1 << ' ' << index << '\n';
                continue;
            }
            out << line << '\n';
        }
        if (is_root && !saw_version)
            throw UserError(file.string() + ":1:1: error: no #version line");
        stack.pop_back();
    }
};

}  // namespace

ShaderSource assemble_shader(const fs::path& file, const std::vector<std::string>& defines) {
    Assembler a;
    a.append(file, true, defines);
    return {a.out.str(), a.files};
}

std::string map_info_log(std::string_view log, const std::vector<std::string>& files) {
    std::ostringstream out;
    std::size_t pos = 0;
    while (pos < log.size()) {
        auto end = log.find('\n', pos);
        if (end == std::string_view::npos) end = log.size();
        std::string_view line = log.substr(pos, end - pos);
        pos = end + 1;
        if (line.empty()) continue;
        // Parse a leading source number.
        std::size_t i = 0;
        auto read_int = [&](int& v) {
            const std::size_t start = i;
            v = 0;
            while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) {
                v = v * 10 + (line[i] - '0');
                ++i;
            }
            return i > start;
        };
        int source = 0, row = 0, col = 0;
        bool mapped = false;
        if (read_int(source) && source >= 0 && source < static_cast<int>(files.size())) {
            if (i < line.size() && line[i] == ':') {  // Mesa: N:L(C): msg
                ++i;
                if (read_int(row) && i < line.size() && line[i] == '(') {
                    ++i;
                    read_int(col);
                    if (i < line.size() && line[i] == ')') ++i;
                    mapped = true;
                }
            } else if (i < line.size() && line[i] == '(') {  // NVIDIA: N(L) : msg
                ++i;
                if (read_int(row) && i < line.size() && line[i] == ')') {
                    ++i;
                    col = 1;
                    mapped = true;
                }
            }
        }
        if (mapped) {
            while (i < line.size() && (line[i] == ' ' || line[i] == ':')) ++i;
            out << files[static_cast<std::size_t>(source)] << ':' << row << ':' << std::max(col, 1)
                << ": " << line.substr(i) << '\n';
        } else {
            out << line << '\n';
        }
    }
    return out.str();
}

namespace {

bool is_ident_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// The text with comments blanked out (newlines kept), so a commented-out declaration is none.
std::string without_comments(std::string_view s) {
    std::string out(s);
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            const auto end = out.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? out.size() : end + 2;
            for (; i < stop; ++i)
                if (out[i] != '\n') out[i] = ' ';
            --i;
        }
    }
    return out;
}

}  // namespace

std::vector<std::string> declared_uniforms(std::string_view glsl) {
    const std::string text = without_comments(glsl);
    std::vector<std::string> names;
    std::size_t pos = 0;
    while ((pos = text.find("uniform", pos)) != std::string::npos) {
        const bool word = (pos == 0 || !is_ident_char(text[pos - 1])) &&
                          (pos + 7 >= text.size() || !is_ident_char(text[pos + 7]));
        pos += 7;
        if (!word) continue;
        // The declaration runs to its ';'. A '{' before it makes it a uniform block.
        const auto end = text.find(';', pos);
        if (end == std::string::npos) break;
        const std::string_view decl(text.data() + pos, end - pos);
        if (decl.find('{') != std::string_view::npos) {
            pos = end;
            continue;
        }
        // Each declarator is the last identifier before a ',', '[' or '=' at nesting depth 0, or
        // before the ';' (the type and qualifiers come first; array sizes and initialisers are
        // skipped by depth).
        int depth = 0;
        std::string last;
        bool taken = false;  // this declarator's name is already recorded
        for (std::size_t i = 0; i <= decl.size(); ++i) {
            const char c = i < decl.size() ? decl[i] : ';';
            if (depth == 0 && is_ident_char(c)) {
                std::size_t j = i;
                while (j < decl.size() && is_ident_char(decl[j])) ++j;
                if (!taken) last = std::string(decl.substr(i, j - i));
                i = j - 1;
                continue;
            }
            if (c == '(' || c == '[') {
                if (depth == 0 && c == '[' && !taken && !last.empty()) {
                    names.push_back(last);
                    taken = true;
                }
                ++depth;
            } else if (c == ')' || c == ']') {
                depth = std::max(0, depth - 1);
            } else if (depth == 0 && (c == '=' || c == ',' || c == ';')) {
                if (!taken && !last.empty() && !std::isdigit(static_cast<unsigned char>(last[0])))
                    names.push_back(last);
                taken = c == '=';  // an initialiser's identifiers are not names
                if (c == ',') last.clear();
            }
        }
        pos = end;
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

}  // namespace bz::gl
