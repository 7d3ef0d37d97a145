#include "level/sections/suggest.h"

#include <algorithm>
#include <vector>

namespace bz::level {

namespace {

char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

// Typos get long words wrong in more places than short ones, but a one-letter key suggesting
// any other one-letter key would be noise.
std::size_t max_edits(std::size_t length) {
    return std::max<std::size_t>(1, length / 3);
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            const std::size_t substitute = diagonal + (lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1);
            row[j] = std::min({above + 1, row[j - 1] + 1, substitute});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::string closest(std::string_view word, std::span<const std::string_view> candidates) {
    // Comparing a huge key against every candidate would cost |word| * |candidate| each; no
    // candidate is long, so anything far longer cannot be within the edit limit anyway.
    constexpr std::size_t kLongest = 64;
    if (word.empty() || word.size() > kLongest) return {};
    std::string_view best;
    std::size_t best_distance = max_edits(word.size()) + 1;
    for (const auto candidate : candidates) {
        const std::size_t d = edit_distance(word, candidate);
        if (d < best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    return std::string(best);
}

std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates) {
    const std::string best = closest(word, candidates);
    if (best.empty()) return {};
    return "; did you mean '" + best + "'?";
}

}  // namespace bz::level
