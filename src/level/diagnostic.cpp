#include "level/diagnostic.h"

#include <algorithm>
#include <cstdio>

#include "core/text/printable.h"

namespace bz::level {

std::string format(const Diagnostic& d) {
    // The file name came from the command line or a level; the message may quote file text.
    std::string out = printable(d.pos.file);
    if (d.pos.line > 0) {
        out += ':' + std::to_string(d.pos.line) + ':' + std::to_string(d.pos.column);
    }
    out += ": error: ";
    out += printable_message(d.message);
    return out;
}

std::string where(const SourcePos& pos) {
    if (pos.file.empty()) return {};
    return printable(pos.file) + ':' + std::to_string(pos.line) + ':' + std::to_string(pos.column) +
           ": ";
}

std::string quote(std::string_view text, std::size_t max_chars) {
    std::string out = "'";
    std::size_t shown = 0;
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        const bool continuation = (c & 0xc0) == 0x80;  // never cut a UTF-8 sequence in two
        if (shown == max_chars && !continuation) {
            out += "...";
            break;
        }
        if (c == '\'' || c == '\\') {
            out += '\\';
            out += ch;
        } else if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += ch;
        }
        if (!continuation) ++shown;
    }
    out += '\'';
    return out;
}

void sort_by_position(std::vector<Diagnostic>& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                         if (a.pos.line != b.pos.line) return a.pos.line < b.pos.line;
                         return a.pos.column < b.pos.column;
                     });
}

}  // namespace bz::level
