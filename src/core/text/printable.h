#pragma once
// Text that came from a file or the command line, made safe to print in a message: control
// characters (newline, NUL, the ESC that starts a terminal escape sequence, the C1 controls) and
// bytes that are not UTF-8 become visible escapes, and a long text is cut with a note of how
// much was left out, so one hostile value cannot fill the terminal or rewrite it.
#include <cstddef>
#include <string>
#include <string_view>

namespace bz {

// Enough to recognise any real key, path or value in a message.
inline constexpr std::size_t kPrintableMaxBytes = 200;

// `text` with escapes (\n, \t, \r, \0, \e, \xNN), at most `max_bytes` of it.
std::string printable(std::string_view text, std::size_t max_bytes = kPrintableMaxBytes);

}  // namespace bz
