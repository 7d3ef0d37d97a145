#include "scene/vector_font.h"

#include <algorithm>
#include <charconv>
#include <string>

#include "core/budgets.h"
#include "core/error.h"
#include "core/io/file_io.h"
#include "core/paths.h"

namespace bz::scene {

namespace {

// A .jhf record: columns 1-5 glyph number, 6-8 vertex count (the margin pair included), then
// that many two-character pairs, each character an offset from 'R'. " R" lifts the pen.
// Long records may continue on the following lines.
constexpr std::size_t kHeaderChars = 8;
constexpr char kOrigin = 'R';

struct Cursor {
    std::string_view text;
    std::size_t pos = 0;
    int line = 0;  // 1-based number of the line `next_line` returned last

    bool next_line(std::string_view& out) {
        if (pos >= text.size()) return false;
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        out = text.substr(pos, end - pos);
        if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
        pos = end + 1;
        ++line;
        return true;
    }
};

[[noreturn]] void fail(const std::filesystem::path& file, int line, std::size_t column,
                       const std::string& what) {
    throw UserError(file.string() + ":" + std::to_string(line) + ":" + std::to_string(column) +
                    ": error: " + what);
}

int parse_count(std::string_view field) {
    while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
    int value = -1;
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (ec != std::errc() || end != field.data() + field.size()) return -1;
    return value;
}

bool valid_coordinate(char c) {
    return c >= ' ' && c <= '~';
}

}  // namespace

VectorFont::VectorFont(const std::filesystem::path& jhf_file) {
    // A Hershey font is a few kilobytes; the cap keeps a wrong path from reading gigabytes.
    const std::string text = read_file(jhf_file, budget::kFontBytes);
    Cursor cursor{text};
    std::string_view line;
    while (cursor.next_line(line)) {
        if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
        const int first_line = cursor.line;
        if (line.size() < kHeaderChars) {
            fail(jhf_file, first_line, line.size() + 1,
                 "glyph record is shorter than its 8-character header");
        }
        const int count = parse_count(line.substr(5, 3));
        if (count < 1) {
            fail(jhf_file, first_line, 6,
                 "vertex count '" + std::string(line.substr(5, 3)) + "' is not a positive number");
        }
        std::string pairs(line.substr(kHeaderChars));
        const std::size_t want = 2 * static_cast<std::size_t>(count);
        while (pairs.size() < want) {
            std::string_view more;
            if (!cursor.next_line(more)) {
                fail(jhf_file, first_line, kHeaderChars + 1,
                     "glyph declares " + std::to_string(count) + " vertices but has only " +
                         std::to_string(pairs.size() / 2) + " before the end of the file");
            }
            pairs += more;
        }
        if (pairs.size() != want) {
            fail(jhf_file, cursor.line, kHeaderChars + 1,
                 "glyph declares " + std::to_string(count) + " vertices but has " +
                     std::to_string(pairs.size() / 2) + (pairs.size() % 2 ? ".5" : ""));
        }
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            if (!valid_coordinate(pairs[i])) {
                // Column is exact for single-line records, which is every record in practice.
                fail(jhf_file, cursor.line, kHeaderChars + 1 + i,
                     "coordinate character with code " +
                         std::to_string(static_cast<unsigned char>(pairs[i])) +
                         " is outside ' '..'~'");
            }
        }

        Glyph g;
        g.left = static_cast<float>(pairs[0] - kOrigin);
        g.right = static_cast<float>(pairs[1] - kOrigin);
        if (g.right < g.left) {
            fail(jhf_file, first_line, kHeaderChars + 1,
                 "glyph's right margin is left of its left");
        }
        std::vector<glm::vec2> stroke;
        for (std::size_t i = 2; i < pairs.size(); i += 2) {
            if (pairs[i] == ' ' && pairs[i + 1] == kOrigin) {
                if (stroke.size() >= 2) g.strokes.push_back(std::move(stroke));
                stroke.clear();
                continue;
            }
            stroke.emplace_back(static_cast<float>(pairs[i] - kOrigin),
                                static_cast<float>(pairs[i + 1] - kOrigin));
        }
        if (stroke.size() >= 2) g.strokes.push_back(std::move(stroke));
        glyphs_.push_back(std::move(g));
    }
    if (glyphs_.empty()) throw UserError(jhf_file.string() + ":1:1: error: no glyphs in font file");

    // Cap height and baseline from 'H' so `height` means what a typographer means by it.
    constexpr std::size_t kH = 'H' - 32;
    if (kH < glyphs_.size() && !glyphs_[kH].strokes.empty()) {
        float top = 1e9f, bottom = -1e9f;
        for (const auto& s : glyphs_[kH].strokes) {
            for (const auto& p : s) {
                top = std::min(top, p.y);
                bottom = std::max(bottom, p.y);
            }
        }
        if (bottom > top) {
            cap_top_ = top;
            baseline_ = bottom;
        }
    }
}

VectorFont VectorFont::load_default() {
    return VectorFont(data_dir() / "fonts" / "futural.jhf");
}

const VectorFont::Glyph* VectorFont::glyph(unsigned char c) const {
    const std::size_t index = c >= 32 ? c - 32u : glyphs_.size();
    return index < glyphs_.size() ? &glyphs_[index] : nullptr;
}

float VectorFont::advance(unsigned char c) const {
    if (const Glyph* g = glyph(c)) return g->right - g->left;
    // Unknown characters take the width of a space (or, in a font without one, nothing).
    if (const Glyph* space = glyph(' ')) return space->right - space->left;
    return 0.0f;
}

float VectorFont::width(std::string_view text, float height) const {
    float units = 0.0f;
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        // UTF-8 continuation bytes belong to the character before; one space per character.
        if ((c & 0xC0u) == 0x80u) continue;
        units += advance(c);
    }
    return units * scale(height);
}

void VectorFont::draw(std::vector<HudLine>& out, std::string_view text, glm::vec2 origin,
                      float height, glm::vec3 color, TextAlign align, float intensity) const {
    const float k = scale(height);
    float pen = origin.x;
    if (align == TextAlign::center) pen -= 0.5f * width(text, height);
    if (align == TextAlign::right) pen -= width(text, height);
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c & 0xC0u) == 0x80u) continue;
        if (const Glyph* g = glyph(c)) {
            for (const auto& stroke : g->strokes) {
                for (std::size_t i = 1; i < stroke.size(); ++i) {
                    HudLine l;
                    // File y grows downward; HUD y grows upward from the baseline.
                    l.a = {pen + (stroke[i - 1].x - g->left) * k,
                           origin.y + (baseline_ - stroke[i - 1].y) * k};
                    l.b = {pen + (stroke[i].x - g->left) * k,
                           origin.y + (baseline_ - stroke[i].y) * k};
                    l.color = color;
                    l.intensity = intensity;
                    out.push_back(l);
                }
            }
        }
        pen += advance(c) * k;
    }
}

}  // namespace bz::scene
