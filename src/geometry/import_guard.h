#pragma once
// Checks that run before a file reaches Assimp, for inputs that make Assimp itself misbehave.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bz::geo::detail {

// Assimp's OFF reader trusts the vertex and face counts in the header and allocates and loops
// over them (a 309-byte file declaring 353 million vertices took 50 s and 16 GB). Given the
// start of a file and its full size, returns a reason to refuse it when it is an OFF file whose
// counts could not fit in that many bytes; nullopt otherwise (including when it is not OFF).
std::optional<std::string> implausible_off_header(std::string_view head, std::uintmax_t file_size);

}  // namespace bz::geo::detail
