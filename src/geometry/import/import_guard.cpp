#include "geometry/import/import_guard.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <limits>
#include <vector>

namespace bz::geo::detail {
namespace {

constexpr std::uintmax_t kHuge = std::numeric_limits<std::uintmax_t>::max();

// Lower bounds on the ASCII encodings: "0 0 0" per vertex, "1 0" per face.
constexpr std::uintmax_t kMinOffVertexBytes = 5;
constexpr std::uintmax_t kMinOffFaceBytes = 3;

std::uintmax_t saturating_mul(std::uintmax_t a, std::uintmax_t b) {
    if (a != 0 && b > kHuge / a) return kHuge;
    return a * b;
}

std::uintmax_t saturating_add(std::uintmax_t a, std::uintmax_t b) {
    return b > kHuge - a ? kHuge : a + b;
}

// Splits the header into whitespace-separated tokens, skipping '#' comments.
class Tokens {
  public:
    explicit Tokens(std::string_view text) : text_(text) {}

    std::string_view next() {
        for (;;) {
            while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
                ++pos_;
            }
            if (pos_ < text_.size() && text_[pos_] == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
                continue;
            }
            break;
        }
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            ++pos_;
        }
        return text_.substr(start, pos_ - start);
    }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
};

// "OFF", "COFF", "NOFF", "STCNOFF", "nOFF": letters ending in OFF.
bool is_off_keyword(std::string_view t) {
    if (t.size() < 3 || t.size() > 8) return false;
    const std::string_view tail = t.substr(t.size() - 3);
    for (std::size_t i = 0; i < 3; ++i) {
        if (std::toupper(static_cast<unsigned char>(tail[i])) != "OFF"[i]) return false;
    }
    for (char c : t) {
        if (!std::isalpha(static_cast<unsigned char>(c))) return false;
    }
    return true;
}

std::optional<std::uintmax_t> parse_count(std::string_view t) {
    std::uintmax_t v = 0;
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec == std::errc::result_out_of_range) return kHuge;  // more than any file holds
    if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
    return v;
}

// Bytes of one binary PLY scalar type; 0 when unknown.
std::uintmax_t ply_type_bytes(std::string_view type) {
    static constexpr std::array<std::pair<std::string_view, std::uintmax_t>, 16> kTypes = {{
        {"char", 1},
        {"uchar", 1},
        {"int8", 1},
        {"uint8", 1},
        {"short", 2},
        {"ushort", 2},
        {"int16", 2},
        {"uint16", 2},
        {"int", 4},
        {"uint", 4},
        {"int32", 4},
        {"uint32", 4},
        {"float", 4},
        {"float32", 4},
        {"double", 8},
        {"float64", 8},
    }};
    for (const auto& [name, bytes] : kTypes) {
        if (name == type) return bytes;
    }
    return 0;
}

struct PlyElement {
    std::string name;
    std::uintmax_t count = 0;
    std::uintmax_t min_bytes = 0;  // fewest bytes one instance can take
};

// Splits a header line into words (PLY headers are one keyword line each).
std::array<std::string_view, 4> words(std::string_view line) {
    std::array<std::string_view, 4> out{};
    std::size_t n = 0, i = 0;
    while (n < out.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= line.size()) break;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        out[n++] = line.substr(start, i - start);
    }
    return out;
}

std::string declared_message(const std::string& format, std::uintmax_t count,
                             const std::string& what, std::uintmax_t available) {
    return format + " header declares " + std::to_string(count) + " " + what + ", more than the " +
           std::to_string(available) + " bytes of data in the file can hold";
}

bool starts_with_ci(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (std::size_t i = 0; i < prefix.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(text[i])) != prefix[i]) return false;
    }
    return true;
}

}  // namespace

std::optional<std::string> implausible_off_header(std::string_view head, std::uintmax_t file_size) {
    Tokens tokens(head);
    const std::string_view keyword = tokens.next();
    if (!is_off_keyword(keyword)) return std::nullopt;
    // "nOFF" puts the space dimension before the counts.
    if (keyword.find('n') != std::string_view::npos && !parse_count(tokens.next())) {
        return std::nullopt;
    }
    const auto vertices = parse_count(tokens.next());
    const auto faces = parse_count(tokens.next());
    if (!vertices || !faces) return std::nullopt;  // Assimp reports malformed headers itself
    const std::uintmax_t need = saturating_add(saturating_mul(*vertices, kMinOffVertexBytes),
                                               saturating_mul(*faces, kMinOffFaceBytes));
    // The last face needs no line end.
    if (need <= saturating_add(file_size, kMinOffFaceBytes)) return std::nullopt;
    return "OFF header declares " + std::to_string(*vertices) + " vertices and " +
           std::to_string(*faces) + " faces, more than a file of " + std::to_string(file_size) +
           " bytes can hold";
}

std::optional<std::string> implausible_ply_header(std::string_view head, std::uintmax_t file_size) {
    if (head.substr(0, 3) != "ply") return std::nullopt;
    std::size_t pos = 0;
    bool ascii = true;
    bool ended = false;
    std::vector<PlyElement> elements;
    while (pos < head.size()) {
        std::size_t eol = head.find('\n', pos);
        if (eol == std::string_view::npos) eol = head.size();
        const std::string_view line = head.substr(pos, eol - pos);
        pos = eol + 1;
        const auto w = words(line);
        if (w[0] == "format") {
            ascii = w[1] == "ascii";
        } else if (w[0] == "element") {
            const auto count = parse_count(w[2]);
            if (!count)
                return "PLY header: element '" + std::string(w[1].substr(0, 40)) +
                       "' has no valid count";
            elements.push_back({std::string(w[1].substr(0, 40)), *count, 0});
        } else if (w[0] == "property" && !elements.empty()) {
            // ascii: a number and a separator at least ("0 "); binary: the type's size; a
            // list costs at least its length field (a list may be empty).
            const std::string_view type = w[1] == "list" ? w[2] : w[1];
            const std::uintmax_t bytes = ascii ? 2 : ply_type_bytes(type);
            elements.back().min_bytes = saturating_add(elements.back().min_bytes, bytes);
        } else if (w[0] == "end_header") {
            ended = true;
            break;
        }
    }
    if (!ended) {
        if (head.size() >= kGuardHeadBytes) {
            return "PLY header has no end_header in its first " + std::to_string(kGuardHeadBytes) +
                   " bytes";
        }
        return std::nullopt;  // a truncated header: Assimp says what is wrong
    }
    const std::uintmax_t body = file_size > pos ? file_size - pos : 0;
    // Slack for files cut a little short, which Assimp reads as far as they go (pond.0.ply in
    // Assimp's own test models lacks 69 of its 2.17 MB); absurd counts are off by far more.
    const std::uintmax_t allowed = saturating_add(saturating_mul(body, 2), 1024);
    std::uintmax_t need = 0;
    for (const PlyElement& e : elements) {
        // An instance with no properties still costs the importer memory: count one byte.
        const std::uintmax_t each = std::max<std::uintmax_t>(e.min_bytes, 1);
        const std::uintmax_t bytes = saturating_mul(e.count, each);
        if (bytes > allowed) {
            return declared_message("PLY", e.count, "'" + e.name + "' elements", body);
        }
        need = saturating_add(need, bytes);
    }
    if (need > allowed) {
        return "PLY header declares elements needing at least " + std::to_string(need) +
               " bytes, more than the " + std::to_string(body) + " bytes of data in the file";
    }
    return std::nullopt;
}

std::optional<std::string> implausible_stl_header(std::string_view head, std::uintmax_t file_size) {
    // ASCII STL starts with "solid" (some binary files do too: they are recognised by size).
    if (head.size() < 84) return std::nullopt;
    std::uint32_t count = 0;
    std::memcpy(&count, head.data() + 80, 4);  // little-endian on every platform we build for
    const std::uintmax_t need = 84 + std::uintmax_t{50} * count;
    if (starts_with_ci(head, "solid") && need != file_size) return std::nullopt;
    if (need <= file_size) return std::nullopt;
    return declared_message("binary STL", count, "triangles", file_size - 84);
}

std::optional<std::string> implausible_declared_counts(std::string_view head,
                                                       std::uintmax_t file_size,
                                                       std::string_view extension) {
    if (auto why = implausible_off_header(head, file_size)) return why;
    if (auto why = implausible_ply_header(head, file_size)) return why;
    if (extension == ".stl") {
        if (auto why = implausible_stl_header(head, file_size)) return why;
    }
    return std::nullopt;
}

std::optional<std::string> too_many_lines(int fd, std::uintmax_t max_lines) {
    std::array<char, 1 << 16> buf{};
    std::uintmax_t lines = 0;
    off_t at = 0;
    for (;;) {
        const ssize_t n = ::pread(fd, buf.data(), buf.size(), at);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        at += n;
        const char* p = buf.data();
        const char* end = p + n;
        while ((p = static_cast<const char*>(
                    std::memchr(p, '\n', static_cast<std::size_t>(end - p))))) {
            ++p;
            if (++lines > max_lines) {
                return "more than " + std::to_string(max_lines) + " lines, over the limit";
            }
        }
    }
    return std::nullopt;
}

}  // namespace bz::geo::detail
