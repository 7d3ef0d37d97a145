#pragma once
// Upper case for the vector font, which draws only ASCII capitals: bytes outside a-z (UTF-8
// included) pass through unchanged, whatever the C locale.
#include <string>

namespace bz {

inline std::string ascii_upper(std::string s) {
    for (char& c : s) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    return s;
}

}  // namespace bz
