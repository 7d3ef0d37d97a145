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

}  // namespace bz::gl
