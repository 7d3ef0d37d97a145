#pragma once
// The readers of each part of a level file, used by the loader in this order: field and
// player first, since obstacle placement is checked against them.
#include <filesystem>
#include <string_view>
#include <vector>

#include "core/text/toml.h"
#include "level/level.h"
#include "level/loader.h"
#include "level/sections/model_path.h"
#include "level/sections/table_reader.h"

namespace bz::level::detail {

// Limits shared by several readers (world units unless named otherwise).
inline constexpr Range kHeightRange{-100.0, 1000.0};
inline constexpr Range kHeadingRange{-360.0, 360.0};
inline constexpr double kMinFieldSize = 50.0;
inline constexpr double kMaxFieldSize = 10000.0;

struct ReadContext {
    Diagnostics& diag;
    const LoadOptions& options;
    ModelRoots model_roots;
    std::vector<std::filesystem::path>& dependencies;
    // Limits that later checks take from earlier sections. When [field] size or the player's
    // position is itself wrong, checks that depend on it are relaxed instead of piling up
    // follow-on errors about a value the author never wrote.
    double position_limit = kMaxFieldSize / 2.0;  // |x|, |z| of anything placed on the field
    bool start_known = true;
};

// The sub-table `key` of `root`, or nullptr when it is absent or not a table (reported).
const toml::table* section(const toml::table& root, std::string_view key, Diagnostics& diag);
// The array `key` of tables ([[key]] or key = [{...}]); nullptr when absent, mistyped or
// longer than `max_count` (reported).
const toml::array* table_array(const toml::table& root, std::string_view key, std::size_t max_count,
                               std::string_view plural, Diagnostics& diag);

// The keys each table allows, for "unknown key" checks and suggestions.
std::span<const std::string_view> root_keys();

void read_field(const toml::table& root, Level& level, glm::vec3& obstacle_color, ReadContext& ctx);
void read_player(const toml::table& root, Level& level, ReadContext& ctx);
void read_enemies(const toml::table& root, Level& level, ReadContext& ctx);
void read_backdrop(const toml::table& root, Level& level, ReadContext& ctx);
void read_render(const toml::table& root, Level& level, Diagnostics& diag);
void read_obstacles(const toml::table& root, Level& level, glm::vec3 default_color,
                    ReadContext& ctx);
void read_camera_path(const toml::table& root, Level& level, ReadContext& ctx);

}  // namespace bz::level::detail
