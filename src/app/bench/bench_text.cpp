#include "app/bench/bench_text.h"

#include <cstdarg>
#include <cstdio>

namespace bz::app {

std::string printf_text(const char* format, ...) {
    char buf[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buf, sizeof buf, format, args);
    va_end(args);
    return buf;
}

}  // namespace bz::app
