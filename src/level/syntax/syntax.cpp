#include "level/syntax/syntax.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "level/syntax/toml_scan.h"

static_assert(TOML_EXCEPTIONS, "the level loader expects toml++ to report errors by exception");

namespace bz::level {

namespace {

// toml++ says "Error while parsing key-value pair: expected value, saw '\n'"; a level author
// wants "syntax error in key-value pair: expected value, saw '\n'".
std::string plain_message(std::string_view description) {
    constexpr std::string_view kPrefix = "Error while parsing ";
    std::string text;
    if (description.substr(0, kPrefix.size()) == kPrefix) {
        text = "syntax error in ";
        text += description.substr(kPrefix.size());
    } else {
        text = "syntax error: ";
        text += description;
        if (text.size() > 14 && text[14] >= 'A' && text[14] <= 'Z') {
            text[14] = static_cast<char>(text[14] - 'A' + 'a');
        }
    }
    std::string out;
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += ch;
        }
    }
    return out;
}

SourcePos position_of_offset(std::string_view text, std::size_t offset, const std::string& file) {
    SourcePos pos{file, 1, 1};
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++pos.line;
            pos.column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xc0) != 0x80) {
            ++pos.column;
        }
    }
    return pos;
}

// Offset of the line on which the statement holding `offset` began: the line itself, or an
// earlier one when a multi-line value (array, inline table, string) is still open there.
std::size_t statement_start(std::string_view text, std::size_t offset) {
    ScanState state;
    std::size_t statement = 0;
    std::size_t pos = 0;
    while (pos < offset) {
        std::size_t end = text.find('\n', pos);
        end = (end == std::string_view::npos || end >= offset) ? offset : end + 1;
        const bool was_inside = state.inside_value();
        if (!was_inside) statement = pos;
        scan(text, pos, end, state);
        pos = end;
    }
    return state.inside_value() ? statement : offset;
}

// Blanks the statement around the error on `line` (with every line of a multi-line value in
// it) by spaces, so all later lines and columns stay where they were. Returns the last line
// blanked and where the statement began, or line 0 when there is nothing left to blank.
struct Blanked {
    int last_line = 0;
    std::size_t start = 0;
};
Blanked blank_statement(std::string& text, int line) {
    const std::size_t error_line = line_start(text, line);
    if (error_line == std::string::npos || error_line >= text.size()) return {};
    const std::size_t start = statement_start(text, error_line);
    std::size_t pos = start;
    int current = line - static_cast<int>(std::count(
                             text.begin() + static_cast<std::ptrdiff_t>(pos),
                             text.begin() + static_cast<std::ptrdiff_t>(error_line), '\n'));
    ScanState own;
    for (;;) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        scan(text, pos, end + 1, own);
        for (std::size_t i = pos; i < end; ++i) text[i] = ' ';
        pos = end + 1;
        if ((current >= line && !own.inside_value()) || pos >= text.size()) return {current, start};
        ++current;
    }
}

// Everything before `resume` has been parsed or skipped. Cutting it down to its line breaks
// keeps every later line and column where it was, and makes the next parse read only the rest,
// so a big file with many errors near its end costs one full parse, not one per error. The
// last table header before the skipped statement (at `statement`) stays, so the keys that
// follow still land in their table.
void drop_parsed_part(std::string& text, std::size_t statement, std::size_t resume) {
    std::size_t header_begin = 0;
    std::size_t header_end = 0;
    ScanState state;
    std::size_t pos = 0;
    while (pos < statement) {
        std::size_t end = text.find('\n', pos);
        end = (end == std::string::npos || end >= statement) ? statement : end + 1;
        if (!state.inside_value()) {
            std::size_t first = pos;
            while (first < end && (text[first] == ' ' || text[first] == '\t')) ++first;
            if (first < end && text[first] == '[') {
                header_begin = pos;
                header_end = end;
            }
        }
        scan(text, pos, end, state);
        pos = end;
    }
    std::string kept;
    kept.reserve(text.size() - resume + 1024);
    for (std::size_t i = 0; i < resume && i < text.size(); ++i) {
        if ((i >= header_begin && i < header_end) || text[i] == '\n') kept += text[i];
    }
    if (resume < text.size()) kept.append(text, resume, std::string::npos);
    text = std::move(kept);
}

// After a syntax error on `line`: skips the broken statement and what came before it. Returns
// the last line skipped, or 0 when parsing cannot usefully go on.
int skip_error(std::string& text, int line) {
    const Blanked b = blank_statement(text, line);
    if (b.last_line == 0) return 0;
    const std::size_t next = line_start(text, b.last_line + 1);
    drop_parsed_part(text, b.start, next == std::string::npos ? text.size() : next);
    return b.last_line;
}

// The end of the last line before `line` that holds more than blanks and a comment.
struct LineEnd {
    int line = 0;    // 0: there is none
    int column = 0;  // just past its last character
    char last = 0;   // that character
};
LineEnd end_of_previous_line(std::string_view text, int line) {
    for (int l = line - 1; l >= 1; --l) {
        const std::size_t begin = line_start(text, l);
        if (begin == std::string_view::npos) continue;
        std::size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        std::string_view content = text.substr(begin, end - begin);
        // A comment ends the line's content (a '#' inside a string is rare on such a line, and
        // a wrong guess only moves the column).
        ScanState state;
        std::size_t code_end = 0;
        for (std::size_t i = 0; i < content.size(); ++i) {
            scan(content, i, i + 1, state);
            if (state.in == ScanState::In::comment) break;
            if (content[i] != ' ' && content[i] != '\t' && content[i] != '\r') code_end = i + 1;
        }
        if (code_end == 0) continue;
        int column = 1;
        for (std::size_t i = 0; i < code_end; ++i) {
            if ((static_cast<unsigned char>(content[i]) & 0xc0) != 0x80) ++column;
        }
        return {l, column, content[code_end - 1]};
    }
    return {};
}

// toml++ notices a missing ']' only where the next line's key stands where a ',' or ']' should
// be, and reports that line. When the error is of that kind, stands at the start of its line,
// and the line before ends like a finished value (not with ',' or '['), the bracket is
// missing at the end of that line: report it there.
std::optional<Diagnostic> missing_bracket(std::string_view text, int line, int column,
                                          std::string_view description, const std::string& file) {
    if (description.find("']'") == std::string_view::npos) return std::nullopt;
    const std::size_t begin = line_start(text, line);
    if (begin == std::string_view::npos) return std::nullopt;
    std::size_t first = begin;
    while (first < text.size() && (text[first] == ' ' || text[first] == '\t')) ++first;
    if (static_cast<int>(first - begin) + 1 != column) return std::nullopt;
    if (statement_start(text, begin) == begin) return std::nullopt;  // no value open here
    const LineEnd prev = end_of_previous_line(text, line);
    if (prev.line == 0 || prev.last == ',' || prev.last == '[' || prev.last == '{')
        return std::nullopt;
    return Diagnostic{SourcePos{file, prev.line, prev.column},
                      "syntax error: missing ']' at the end of this line (the array is not "
                      "closed before line " +
                          std::to_string(line) + ")"};
}

}  // namespace

SyntaxResult parse_toml(std::string_view text, const std::string& file, std::size_t max_errors) {
    SyntaxResult result;
    if (const auto deep = find_deep_key(text, kMaxKeyDots)) {
        std::size_t at = deep->offset;
        while (at < text.size() && (text[at] == ' ' || text[at] == '\t')) ++at;
        result.errors.push_back({position_of_offset(text, at, file),
                                 "key is nested more than " + std::to_string(kMaxKeyDots) +
                                     " levels deep (too many dots)"});
        return result;
    }
    std::string work(text);
    int blanked_through = 0;
    for (;;) {
        if (const auto unsafe = find_unsafe_char(work)) {
            const SourcePos at = position_of_offset(work, unsafe->offset, file);
            result.errors.push_back({at, std::string("syntax error: ") + unsafe->why});
            if (result.errors.size() >= max_errors || at.line <= blanked_through) return result;
            const int last = skip_error(work, at.line);
            if (last == 0) return result;
            blanked_through = last;
            continue;
        }
        try {
            toml::table table = toml::parse(std::string_view(work), std::string_view(file));
            if (result.errors.empty()) result.table = std::move(table);
            return result;
        } catch (const toml::parse_error& e) {
            // toml++ counts from 1; the clamp keeps "file:line:col" well-formed regardless.
            const int line = std::max(1, static_cast<int>(e.source().begin.line));
            const int column = std::max(1, static_cast<int>(e.source().begin.column));
            if (auto moved = missing_bracket(work, line, column, e.description(), file)) {
                result.errors.push_back(std::move(*moved));
            } else {
                result.errors.push_back(
                    {SourcePos{file, line, column}, plain_message(e.description())});
            }
            if (result.errors.size() >= max_errors || line <= blanked_through) return result;
            const int last = skip_error(work, line);
            if (last == 0) return result;
            blanked_through = last;
        }
    }
}

}  // namespace bz::level
