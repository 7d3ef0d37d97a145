#pragma once
// Zip-based model files (.3mf, .zae, .pk3, ...): Assimp inflates every entry it reads into
// one buffer of the size the zip's central directory declares, so a 3 MB .3mf whose model
// inflates to 3 GB took 3.1 GB and ended in SIGABRT. The declared sizes are read here first,
// with minizip (the library Assimp itself reads zips with), and refused over the cap.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bz::geo::detail {

// True when the file starts like a zip archive (a local header or an empty archive).
bool looks_like_zip(std::string_view head);

// Given an open zip file, returns why it is refused: more uncompressed bytes in all entries
// together than `max_unzipped_bytes`, too many entries, or a central directory minizip cannot
// read. nullopt when it is within the limits.
std::optional<std::string> zip_over_limits(int fd, std::uint64_t max_unzipped_bytes);

}  // namespace bz::geo::detail
