#pragma once
// "Did you mean" for misspelt keys and names.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace bz::level {

// Levenshtein distance (insert, delete, substitute), ASCII case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word` when it is close enough to be a likely typo (at most a
// third of the word's length, and at least one edit), else an empty string.
std::string closest(std::string_view word, std::span<const std::string_view> candidates);

// "; did you mean 'x'?" or "" when nothing is close.
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace bz::level
