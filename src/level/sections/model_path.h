#pragma once
// Where a level may take model files from: a path written relative to the level file that
// stays, after resolving `..` and symlinks, inside the level's own folder or the project's
// data/ folder. Anything else (absolute paths, escapes through `..` or symlinks) is refused so
// a downloaded level cannot make the game read arbitrary files.
#include <filesystem>
#include <string>
#include <string_view>

namespace bz::level {

struct ModelPath {
    std::filesystem::path resolved;  // canonical; empty when refused before resolving
    std::string error;               // empty when the path is usable
    bool watchable = false;          // inside an allowed folder (exists or not): worth watching
};

// The two folders models may come from, made canonical once per level (a big level names
// hundreds of models, and canonicalising costs a system call per path component).
struct ModelRoots {
    std::filesystem::path level_folder;
    std::filesystem::path data_folder;
};
ModelRoots model_roots(const std::filesystem::path& level_dir,
                       const std::filesystem::path& data_root);

ModelPath resolve_model_path(std::string_view text, const ModelRoots& roots);

// True when `path` is `folder` or lies below it; both must already be canonical.
bool is_inside(const std::filesystem::path& path, const std::filesystem::path& folder);

// The file name extensions model files may have (lower case, with the dot).
bool is_model_extension(std::string_view extension);

}  // namespace bz::level
