#pragma once
// Turns level text into a TOML table, or into every syntax error it can find: after an error
// it blanks the broken statement and parses again, so one typo does not hide the next.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/text/toml.h"
#include "level/diagnostic.h"

namespace bz::level {

struct SyntaxResult {
    std::optional<toml::table> table;  // set only when there were no syntax errors
    std::vector<Diagnostic> errors;
};

SyntaxResult parse_toml(std::string_view text, const std::string& file, std::size_t max_errors);

// Deeper dotted keys are refused before toml++ sees them (it recurses once per level).
inline constexpr int kMaxKeyDots = 32;

}  // namespace bz::level
