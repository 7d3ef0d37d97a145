#pragma once
// How a model import refuses a file, in the import process and in the game alike.
#include <filesystem>
#include <string>

namespace bz::geo {

// Throws UserError("path: error: reason") on one line: the path escaped as every value in a
// message is, and the reason (which may quote an importer's multi-line text) with its control
// characters escaped and its line breaks turned to spaces.
[[noreturn]] void fail_import(const std::filesystem::path& path, const std::string& reason);

}  // namespace bz::geo
