#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace bz {

// Reads a whole file. Throws UserError naming the file when it is missing, unreadable, not a
// regular file or larger than max_bytes (so a hostile path such as /dev/zero cannot hang us).
std::string read_file(const std::filesystem::path& path, std::size_t max_bytes = 64u << 20);

// Writes a file so that a crash at any moment leaves either the old or the new content:
// write a temp file in the same folder, fsync it, rename over the target, fsync the folder.
// A symbolic link is written through (its target is replaced; the link stays). The folder
// must exist. Throws UserError on failure; the old file is untouched then.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

}  // namespace bz
