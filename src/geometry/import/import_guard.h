#pragma once
// Checks that run before a file reaches Assimp, for inputs that make Assimp itself misbehave:
// formats whose headers declare element counts that Assimp trusts, allocating and looping over
// them before it notices the file is far too short (a 190-byte PLY declaring 1.5e9 vertices
// grew the game to 17.6 GB). Each guard bounds the declared counts by what a file of the given
// size could hold, at the fewest bytes per element the format allows.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bz::geo::detail {

// How much of a file the header guards look at: headers longer than this are refused.
inline constexpr std::size_t kGuardHeadBytes = std::size_t{1} << 20;

// OFF ("OFF", "COFF", "NOFF", "nOFF" with its dimension, ...): vertex and face counts.
std::optional<std::string> implausible_off_header(std::string_view head, std::uintmax_t file_size);

// PLY, ascii or binary: every `element NAME COUNT` against the bytes after `end_header`.
std::optional<std::string> implausible_ply_header(std::string_view head, std::uintmax_t file_size);

// Binary STL: the triangle count at byte 80 against 50 bytes per triangle.
std::optional<std::string> implausible_stl_header(std::string_view head, std::uintmax_t file_size);

// Every guard above, chosen by the file's content (Assimp also looks at content, so a PLY
// named .obj is still a PLY) and extension (lower case, with the dot).
std::optional<std::string> implausible_declared_counts(std::string_view head,
                                                       std::uintmax_t file_size,
                                                       std::string_view extension);

// For text formats without declared counts (OBJ): more than `max_lines` lines is refused, as
// the importer's memory grows with every line (about 15 times the file size for faces).
std::optional<std::string> too_many_lines(int fd, std::uintmax_t max_lines);

}  // namespace bz::geo::detail
