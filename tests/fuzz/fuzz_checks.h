#pragma once
// What every parser's message must look like, checked by the fuzz targets: it names the file
// (with line and column where `positioned`), holds no control character (untrusted text is
// escaped) and stays short (untrusted text is cut).
#include <string_view>

namespace bz::fuzz {

inline void check_message(std::string_view message, std::string_view file_prefix, bool positioned) {
    if (message.substr(0, file_prefix.size()) != file_prefix) __builtin_trap();
    if (message.size() > 2000) __builtin_trap();
    for (const char c : message) {
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) __builtin_trap();
    }
    if (positioned) {
        // FILE:LINE:COL: with LINE and COL at least 1.
        std::string_view rest = message.substr(file_prefix.size());
        for (int part = 0; part < 2; ++part) {
            std::size_t digits = 0;
            while (digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9') ++digits;
            if (digits == 0 || rest[0] == '0' || digits >= rest.size() || rest[digits] != ':')
                __builtin_trap();
            rest.remove_prefix(digits + 1);
        }
    }
}

}  // namespace bz::fuzz
