#include "level/watcher.h"

#include <sys/stat.h>

#include <algorithm>

namespace bz::level {
namespace fs = std::filesystem;

LevelWatcher::LevelWatcher(fs::path file, LoadOptions options)
    : file_(std::move(file)), options_(std::move(options)) {
    reload();
}

LevelWatcher::Stamp LevelWatcher::stamp(const fs::path& path) {
    Stamp s;
    s.path = path;
    struct ::stat st {};
    if (::stat(path.c_str(), &st) != 0) return s;
    s.exists = true;
    s.size = static_cast<std::uint64_t>(st.st_size);
    s.mtime_ns = static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
    s.inode = static_cast<std::uint64_t>(st.st_ino);
    return s;
}

void LevelWatcher::reload() {
    // Stamp before reading: a save that lands while we read is then seen by the next poll.
    std::vector<Stamp> before;
    before.push_back(stamp(file_));
    LoadResult result = load_level_file(file_, options_);
    // The level file comes first in dependencies; stamp the models it named.
    std::vector<fs::path> models(result.dependencies.begin() + 1, result.dependencies.end());
    if (current_) {
        for (const auto& o : current_->obstacles) {
            if (!o.model.empty()) models.push_back(o.model);
        }
    }
    std::sort(models.begin(), models.end());
    models.erase(std::unique(models.begin(), models.end()), models.end());
    for (const auto& m : models) before.push_back(stamp(m));
    stamps_ = std::move(before);
    errors_ = std::move(result.errors);
    if (result.level) {
        current_ = std::move(result.level);
        ++generation_;
    }
}

bool LevelWatcher::poll() {
    for (const auto& s : stamps_) {
        if (stamp(s.path) != s) {
            reload();
            return true;
        }
    }
    return false;
}

std::vector<fs::path> LevelWatcher::watched() const {
    std::vector<fs::path> out;
    out.reserve(stamps_.size());
    for (const auto& s : stamps_) out.push_back(s.path);
    return out;
}

}  // namespace bz::level
