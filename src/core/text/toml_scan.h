#pragma once
// A small lexical pass over TOML text that knows only strings, comments and brackets. It lets
// the syntax checker guard toml++ against inputs it handles badly (keys nested thousands of
// levels deep overflow its stack) and tell where a broken statement ends, so parsing can resume
// after it and report the next syntax error too.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace bz {

struct ScanState {
    enum class In { code, comment, basic, literal, multiline_basic, multiline_literal };
    In in = In::code;
    bool escaped = false;  // the previous character was a backslash inside a basic string
    // The last character seen outside strings and comments. A quote opens a string only after
    // whitespace, '=', '[', '{' or ','; elsewhere (as in 1:*'x') toml++ is still reading a
    // bare value and so is this scanner.
    char previous_code = '\n';
    // Where a key may stand: at a line's start (until '='), after '{' or a ',' in an inline
    // table, inside a table header. There a quote after a dot opens a quoted key segment
    // (a." b" = 1); in a value toml++ reads 1."b" on as one bare value.
    bool key_position = true;
    std::string brackets;  // the open '[' and '{' (arrays, inline tables, headers), innermost last
    // A value that spans lines (open brackets, multi-line string) is still being read.
    bool inside_value() const {
        return !brackets.empty() || in == In::multiline_basic || in == In::multiline_literal;
    }
};

// Advances `state` over text[begin, end).
void scan(std::string_view text, std::size_t begin, std::size_t end, ScanState& state);

// Offset of the first character of 1-based `line`, or npos past the end.
std::size_t line_start(std::string_view text, int line);

struct DeepKey {
    std::size_t offset;  // where the key starts
    int dots;
};

// The first dotted key (or table header) with more than `max_dots` dots, if any.
std::optional<DeepKey> find_deep_key(std::string_view text, int max_dots);

struct UnsafeChar {
    std::size_t offset;
    const char* why;
};

// toml++ 3.3 asks "is this whitespace?" of characters in two places where a non-ASCII
// character reaches a __builtin_unreachable() in its Unicode tables (undefined behaviour):
// outside strings and comments, where TOML forbids non-ASCII anyway, and right after a
// backslash (and the whitespace a line-ending backslash skips) in a multi-line basic string.
// Finds the first such character so it can be reported with a plain message. Safety does not
// rest on this scan (its model of where strings start can differ from toml++'s on garbage:
// the settings fuzz target found such an input); core/text/toml.h corrects the lookup itself.
std::optional<UnsafeChar> find_unsafe_char(std::string_view text);

}  // namespace bz
