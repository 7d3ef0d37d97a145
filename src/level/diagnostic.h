#pragma once
// One problem found in a level file, with where it is.
#include <string>
#include <string_view>
#include <vector>

#include "level/level.h"

namespace bz::level {

struct Diagnostic {
    SourcePos pos;  // problems of the whole file (missing, too large) are at 1:1
    std::string message;
};

// "file:line:col: error: message" ("file: error: message" if a diagnostic has line 0).
std::string format(const Diagnostic& d);

// "file:line:col: " for a message about something at `pos`, the file name escaped as every
// value in a message is; empty when the thing came from no file (built in, generated).
std::string where(const SourcePos& pos);

// Makes text from a level file safe to quote inside a one-line message: control characters
// and quotes become escapes, and anything past `max_chars` is cut and marked with "...".
std::string quote(std::string_view text, std::size_t max_chars = 40);

// Orders by line then column (messages read top to bottom, as the file does).
void sort_by_position(std::vector<Diagnostic>& diagnostics);

}  // namespace bz::level
