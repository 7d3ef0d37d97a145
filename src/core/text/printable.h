#pragma once
// Text that came from a file or the command line, made safe to print in a message: control
// characters (newline, NUL, the ESC that starts a terminal escape sequence, the C1 controls),
// the invisible Unicode format characters that reorder or hide text (bidi overrides such as
// U+202E, zero-width characters, line separators) and bytes that are not UTF-8 become visible
// escapes, and a long text is cut with a note of how much was left out, so one hostile value
// cannot fill the terminal, rewrite it or make a message read other than it is.
#include <cstddef>
#include <string>
#include <string_view>

#include "core/budgets.h"

namespace bz {

// Enough to recognise any real key, path or value in a message.
inline constexpr std::size_t kPrintableMaxBytes = budget::kMessageValueBytes;

// `text` with escapes (\n, \t, \r, \0, \e, \xNN, \u{NNNN}), at most `max_bytes` of it.
std::string printable(std::string_view text, std::size_t max_bytes = kPrintableMaxBytes);

// The last line of defence for a whole message about to be printed (the top level applies it
// to every error): as printable, but its own newlines and tabs stay, and the cap is for the
// whole message. A value that reached a message without printable() still cannot send a
// terminal escape or a bidi override.
std::string printable_message(std::string_view text, std::size_t max_bytes = 64 * 1024);

// A name for one line of a menu: printable, then cut to at most `max_chars` characters (code
// points) with a trailing "..." when longer, so one long file name cannot push the others off
// the screen.
std::string menu_label(std::string_view text, std::size_t max_chars = budget::kMenuLabelChars);

}  // namespace bz
