#pragma once
// Reads and validates level files. Loading never stops at the first problem: it returns every
// error of the file, each with file:line:col, and a Level only when there were none.
#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "core/budgets.h"
#include "core/paths.h"
#include "level/diagnostic.h"
#include "level/level.h"

namespace bz::level {

// The file format version this build reads (the first key of every level file).
inline constexpr int kFormatVersion = 1;

struct LoadOptions {
    // Besides the level's own folder, the one folder model paths may point into.
    std::filesystem::path data_root = bz::data_dir();
    std::size_t max_file_bytes = budget::kLevelBytes;
    std::size_t max_obstacles = 5000;
    std::size_t max_camera_keys = 10000;
    std::size_t max_mountain_points = 4096;
    std::size_t max_errors = 100;  // a broken generated file should not print forever
};

struct LoadResult {
    std::optional<Level> level;      // set exactly when errors is empty
    std::vector<Diagnostic> errors;  // sorted by position
    // The level file and every model path it names that lies in an allowed folder, found or
    // not: what a hot-reload watcher has to watch to notice a fix.
    std::vector<std::filesystem::path> dependencies;
    bool ok() const { return level.has_value(); }
};

// `file_for_messages` names the file in messages and is where model paths are resolved from.
LoadResult load_level_string(std::string_view text, const std::filesystem::path& file_for_messages,
                             const LoadOptions& options = {});
LoadResult load_level_file(const std::filesystem::path& file, const LoadOptions& options = {});

// The skyline (azimuth, height in degrees) a level gets when it does not set
// backdrop.mountains.
std::vector<glm::dvec2> default_mountains();

// levels/classic.toml under the project root.
std::filesystem::path default_level_path();

}  // namespace bz::level
