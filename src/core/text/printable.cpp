#include "core/text/printable.h"

#include <cstdio>

namespace bz {

namespace {

void append_hex(std::string& out, unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", c);
    out += buf;
}

void append_code_point(std::string& out, unsigned cp) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "\\u{%04x}", cp);
    out += buf;
}

struct Decoded {
    std::size_t length = 0;  // 0: not a valid sequence
    unsigned cp = 0;
};

// The valid UTF-8 sequence starting at text[i] (2..4 bytes), or length 0 when it is not one.
// Overlong forms, surrogates and code points past U+10FFFF count as invalid.
Decoded decode_utf8(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    std::size_t n = 0;
    unsigned cp = 0;
    if (c >= 0xc2 && c <= 0xdf) {
        n = 2;
        cp = c & 0x1fu;
    } else if (c >= 0xe0 && c <= 0xef) {
        n = 3;
        cp = c & 0x0fu;
    } else if (c >= 0xf0 && c <= 0xf4) {
        n = 4;
        cp = c & 0x07u;
    } else {
        return {};
    }
    if (i + n > text.size()) return {};
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xc0) != 0x80) return {};
        cp = (cp << 6) | (byte(i + k) & 0x3fu);
    }
    if ((n == 3 && cp < 0x800) || (n == 4 && (cp < 0x10000 || cp > 0x10ffff))) return {};
    if (cp >= 0xd800 && cp <= 0xdfff) return {};
    return {n, cp};
}

// Code points that print nothing yet change how the text around them reads: the C1 controls
// (U+009B is the 8-bit CSI), bidi marks, embeddings, overrides and isolates, zero-width
// characters, line and paragraph separators, the BOM and the invisible tag characters.
bool is_hidden_control(unsigned cp) {
    return (cp >= 0x80 && cp <= 0x9f) || cp == 0x061c || (cp >= 0x200b && cp <= 0x200f) ||
           (cp >= 0x2028 && cp <= 0x202e) || (cp >= 0x2060 && cp <= 0x206f) || cp == 0xfeff ||
           (cp >= 0xfff9 && cp <= 0xfffb) || (cp >= 0xe0000 && cp <= 0xe007f);
}

// Appends text[i..] escaped up to the end of one character; returns the bytes consumed.
std::size_t append_one(std::string& out, std::string_view text, std::size_t i, bool keep_newlines) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
        out += static_cast<char>(c);
        return 1;
    }
    if (c >= 0x80) {
        const Decoded d = decode_utf8(text, i);
        if (d.length == 0) {
            append_hex(out, c);
            return 1;
        }
        if (is_hidden_control(d.cp)) {
            append_code_point(out, d.cp);
        } else {
            out.append(text.substr(i, d.length));
        }
        return d.length;
    }
    if (keep_newlines && (c == '\n' || c == '\t')) {
        out += static_cast<char>(c);
        return 1;
    }
    switch (c) {
        case '\n':
            out += "\\n";
            break;
        case '\t':
            out += "\\t";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\0':
            out += "\\0";
            break;
        case 0x1b:
            out += "\\e";
            break;
        default:
            append_hex(out, c);
    }
    return 1;
}

// Where to cut `text` at most `max_bytes` in without splitting a UTF-8 sequence.
std::size_t cut_point(std::string_view text, std::size_t max_bytes) {
    if (text.size() <= max_bytes) return text.size();
    std::size_t cut = max_bytes;
    // Back off over continuation bytes (at most 3) to the start of the character.
    for (int k = 0; k < 3 && cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xc0) == 0x80; ++k)
        --cut;
    return cut;
}

std::string escape(std::string_view text, std::size_t max_bytes, bool keep_newlines) {
    const std::string_view shown = text.substr(0, cut_point(text, max_bytes));
    std::string out;
    out.reserve(shown.size());
    for (std::size_t i = 0; i < shown.size();) i += append_one(out, shown, i, keep_newlines);
    if (text.size() > shown.size()) {
        out += "... (" + std::to_string(text.size() - shown.size()) + " more bytes)";
    }
    return out;
}

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
    return escape(text, max_bytes, false);
}

std::string printable_message(std::string_view text, std::size_t max_bytes) {
    return escape(text, max_bytes, true);
}

std::string menu_label(std::string_view text, std::size_t max_chars) {
    const std::string safe = escape(text, text.size(), false);
    // Count code points (bytes that do not continue a sequence).
    std::size_t chars = 0;
    for (std::size_t i = 0; i < safe.size(); ++i) {
        if ((static_cast<unsigned char>(safe[i]) & 0xc0) == 0x80) continue;
        if (chars == max_chars) {
            if (max_chars <= 3) return safe.substr(0, i);
            // Cut so that the label with its "..." is max_chars long.
            std::size_t keep = 0, n = 0;
            for (std::size_t j = 0; j < safe.size(); ++j) {
                if ((static_cast<unsigned char>(safe[j]) & 0xc0) == 0x80) continue;
                if (n == max_chars - 3) {
                    keep = j;
                    break;
                }
                ++n;
            }
            return safe.substr(0, keep) + "...";
        }
        ++chars;
    }
    return safe;
}

}  // namespace bz
