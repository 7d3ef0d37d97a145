#pragma once
// Which level file a replay was recorded on, for commands that play one back without being
// told the level (`replay --verify`, `play --replay`).
#include <filesystem>
#include <string>

namespace bz::app {

// A relative level path is tried as given, then next to the replay, then under the project.
std::filesystem::path replay_level_path(const std::string& recorded,
                                        const std::filesystem::path& replay_file);

}  // namespace bz::app
