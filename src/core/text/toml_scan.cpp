#include "core/text/toml_scan.h"

namespace bz {

namespace {

bool starts_with_at(std::string_view text, std::size_t i, std::string_view what) {
    return text.substr(i, what.size()) == what;
}

bool opens_string(const ScanState& s) {
    const char previous = s.previous_code;
    return previous == ' ' || previous == '\t' || previous == '\n' || previous == '\r' ||
           previous == '=' || previous == '[' || previous == '{' || previous == ',' ||
           (previous == '.' && s.key_position);
}

// A new line: a key may start it unless a value (an array) is still open.
void new_line(ScanState& s) {
    s.key_position = s.brackets.empty();
}

// Steps over one character (or a three-quote delimiter); returns how many were consumed.
std::size_t step(std::string_view text, std::size_t i, ScanState& s) {
    using In = ScanState::In;
    const char c = text[i];
    switch (s.in) {
        case In::code:
            if ((c == '"' || c == '\'') && !opens_string(s)) {
                s.previous_code = c;
                return 1;
            }
            s.previous_code = c;
            if (c == '#') {
                s.in = In::comment;
            } else if (c == '"') {
                if (starts_with_at(text, i, "\"\"\"")) {
                    s.in = In::multiline_basic;
                    return 3;
                }
                s.in = In::basic;
            } else if (c == '\'') {
                if (starts_with_at(text, i, "'''")) {
                    s.in = In::multiline_literal;
                    return 3;
                }
                s.in = In::literal;
            } else if (c == '[' || c == '{') {
                s.brackets.push_back(c);
                // '[' keeps the position: a table header's keys, or an array's values.
                if (c == '{') s.key_position = true;
            } else if ((c == ']' || c == '}') && !s.brackets.empty()) {
                s.brackets.pop_back();
                s.key_position = false;
            } else if (c == '=') {
                s.key_position = false;
            } else if (c == ',') {
                s.key_position = !s.brackets.empty() && s.brackets.back() == '{';
            } else if (c == '\n') {
                new_line(s);
            }
            return 1;
        case In::comment:
            if (c == '\n') {
                s.in = In::code;
                s.previous_code = c;
                new_line(s);
            }
            return 1;
        case In::basic:
        case In::multiline_basic:
            if (s.escaped) {
                s.escaped = false;
            } else if (c == '\\') {
                s.escaped = true;
            } else if (s.in == In::basic && (c == '"' || c == '\n')) {
                s.in = In::code;
                s.previous_code = c;
                if (c == '\n') new_line(s);
            } else if (s.in == In::multiline_basic && starts_with_at(text, i, "\"\"\"")) {
                s.in = In::code;
                s.previous_code = c;
                return 3;
            }
            return 1;
        case In::literal:
            if (c == '\'' || c == '\n') {
                s.in = In::code;
                s.previous_code = c;
                if (c == '\n') new_line(s);
            }
            return 1;
        case In::multiline_literal:
            if (starts_with_at(text, i, "'''")) {
                s.in = In::code;
                s.previous_code = c;
                return 3;
            }
            return 1;
    }
    return 1;
}

}  // namespace

void scan(std::string_view text, std::size_t begin, std::size_t end, ScanState& state) {
    if (end > text.size()) end = text.size();
    std::size_t i = begin;
    while (i < end) i += step(text, i, state);
}

std::size_t line_start(std::string_view text, int line) {
    std::size_t offset = 0;
    for (int l = 1; l < line; ++l) {
        offset = text.find('\n', offset);
        if (offset == std::string_view::npos) return offset;
        ++offset;
    }
    return offset <= text.size() ? offset : std::string_view::npos;
}

std::optional<DeepKey> find_deep_key(std::string_view text, int max_dots) {
    // Dots outside strings between two separators belong to one dotted key (a number has at
    // most one), so counting them per stretch bounds the nesting a key can create.
    ScanState state;
    std::size_t stretch_start = 0;
    int dots = 0;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        const bool in_code = state.in == ScanState::In::code;
        if (in_code) {
            if (c == '=' || c == ',' || c == '\n' || c == '[' || c == ']' || c == '{' || c == '}' ||
                c == '#') {
                dots = 0;
                stretch_start = i + 1;
            } else if (c == '.') {
                if (++dots > max_dots) return DeepKey{stretch_start, dots};
            }
        }
        i += step(text, i, state);
    }
    return std::nullopt;
}

std::optional<UnsafeChar> find_unsafe_char(std::string_view text) {
    using In = ScanState::In;
    ScanState state;
    // A byte order mark may open the file; toml++ skips it before parsing.
    std::size_t i = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    bool skipping = false;  // after a line-ending backslash in a multi-line basic string
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        const bool ascii = c < 0x80;
        if (state.in == In::code && !ascii) {
            return UnsafeChar{i, "non-ASCII character outside a string or comment"};
        }
        if (state.in == In::multiline_basic) {
            if (skipping) {
                if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
                    ++i;
                    continue;
                }
                skipping = false;
                if (!ascii) {
                    return UnsafeChar{i,
                                      "non-ASCII character right after a line-ending backslash "
                                      "in a multi-line string (put it before the backslash)"};
                }
            } else if (state.escaped) {
                if (!ascii) {
                    return UnsafeChar{i,
                                      "non-ASCII character after a backslash in a string "
                                      "(not an escape sequence)"};
                }
                if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
                    state.escaped = false;
                    skipping = true;
                    ++i;
                    continue;
                }
            }
        }
        i += step(text, i, state);
    }
    return std::nullopt;
}

}  // namespace bz
