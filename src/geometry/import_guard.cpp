#include "geometry/import_guard.h"

#include <cctype>
#include <charconv>

namespace bz::geo::detail {
namespace {

// Lower bounds on the ASCII encodings: "0 0 0" per vertex, "1 0" per face.
constexpr std::uintmax_t kMinVertexBytes = 5;
constexpr std::uintmax_t kMinFaceBytes = 3;

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

// "OFF", "COFF", "NOFF", "STCNOFF", ...: letters ending in OFF. A lowercase 'n' ("nOFF")
// means a dimension comes before the counts; such files are left to Assimp.
bool is_off_keyword(std::string_view t) {
    if (t.size() < 3 || t.size() > 8 || t.find('n') != std::string_view::npos) return false;
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
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
    return v;
}

}  // namespace

std::optional<std::string> implausible_off_header(std::string_view head, std::uintmax_t file_size) {
    Tokens tokens(head);
    if (!is_off_keyword(tokens.next())) return std::nullopt;
    const auto vertices = parse_count(tokens.next());
    const auto faces = parse_count(tokens.next());
    if (!vertices || !faces) return std::nullopt;  // Assimp reports malformed headers itself
    // Divisions first so huge counts cannot overflow the sum.
    if (*vertices <= file_size / kMinVertexBytes && *faces <= file_size / kMinFaceBytes &&
        *vertices * kMinVertexBytes + *faces * kMinFaceBytes <= file_size + kMinFaceBytes) {
        return std::nullopt;
    }
    return "OFF header declares " + std::to_string(*vertices) + " vertices and " +
           std::to_string(*faces) + " faces, more than a file of " + std::to_string(file_size) +
           " bytes can hold";
}

}  // namespace bz::geo::detail
