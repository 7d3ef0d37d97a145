#pragma once
// Hot reload of one level: poll() notices when the level file or a model file it names has
// changed (size, modification time or inode: editors that save by renaming count too) and
// loads it again. A broken edit keeps the last good level and exposes the new errors until the
// file is fixed. No threads and no SDL: the game calls poll() from its frame loop.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "level/loader.h"

namespace bz::level {

class LevelWatcher {
  public:
    // Loads the file at once; current() stays empty if that first load fails.
    explicit LevelWatcher(std::filesystem::path file, LoadOptions options = {});

    // Cheap when nothing changed (one stat per watched file); call it every frame or a few
    // times a second. Returns true when it reloaded, successfully or not.
    bool poll();
    // Loads again whether or not anything changed.
    void reload();

    // The last level that loaded without errors.
    const std::optional<Level>& current() const { return current_; }
    // Errors of the latest load; empty when it was clean.
    const std::vector<Diagnostic>& errors() const { return errors_; }
    // Bumps each time a new good level becomes current (starts at 1 after a clean first load).
    std::uint64_t generation() const { return generation_; }
    const std::filesystem::path& file() const { return file_; }
    // The files whose changes trigger a reload.
    std::vector<std::filesystem::path> watched() const;

  private:
    struct Stamp {
        std::filesystem::path path;
        bool exists = false;
        std::uint64_t size = 0;
        std::int64_t mtime_ns = 0;
        std::uint64_t inode = 0;
        bool operator==(const Stamp&) const = default;
    };
    static Stamp stamp(const std::filesystem::path& path);

    std::filesystem::path file_;
    LoadOptions options_;
    std::optional<Level> current_;
    std::vector<Diagnostic> errors_;
    std::uint64_t generation_ = 0;
    std::vector<Stamp> stamps_;
};

}  // namespace bz::level
