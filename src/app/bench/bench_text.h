#pragma once
// printf-style text for the bench's goal lines and tables. A C variadic with the format
// attribute, so the compiler checks each call's format against its arguments.
#include <string>

namespace bz::app {

std::string printf_text(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace bz::app
