#include "geometry/import/confined_io.h"

#include <unistd.h>

#include <assimp/IOStream.hpp>
#include <cstdio>
#include <memory>
#include <utility>

#include "core/io/regular_file.h"

namespace bz::geo::detail {
namespace {

namespace fs = std::filesystem;

// A read-only stream over a FILE* opened from an already checked descriptor.
class FileStream final : public Assimp::IOStream {
  public:
    FileStream(std::FILE* file, std::uintmax_t size) : file_(file), size_(size) {}
    ~FileStream() override { std::fclose(file_); }
    FileStream(const FileStream&) = delete;
    FileStream& operator=(const FileStream&) = delete;

    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0 || count == 0) return 0;
        return std::fread(buffer, size, count, file_);
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        const int whence = origin == aiOrigin_SET   ? SEEK_SET
                           : origin == aiOrigin_CUR ? SEEK_CUR
                                                    : SEEK_END;
        return std::fseek(file_, static_cast<long>(offset), whence) == 0 ? aiReturn_SUCCESS
                                                                         : aiReturn_FAILURE;
    }
    size_t Tell() const override { return static_cast<size_t>(std::ftell(file_)); }
    size_t FileSize() const override { return static_cast<size_t>(size_); }
    void Flush() override {}

  private:
    std::FILE* file_;
    std::uintmax_t size_;
};

bool inside(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        if (f->empty() && std::next(f) == folder.end()) break;  // trailing separator
        if (p == path.end() || *p != *f) return false;
    }
    return true;
}

// A file reference as the message quotes it: printable, and at most 120 bytes, the middle cut
// out (marked "...") so that both the folder it starts from and the file name still show.
std::string shown(const char* text) {
    constexpr std::size_t kMax = 120;
    std::string out;
    for (const char* c = text; *c; ++c) {
        const auto u = static_cast<unsigned char>(*c);
        out.push_back(u >= 0x20 && u < 0x7f ? *c : '?');
    }
    if (out.size() <= kMax) return out;
    constexpr std::size_t kKeep = (kMax - 3) / 2;
    return out.substr(0, kKeep) + "..." + out.substr(out.size() - kKeep);
}

}  // namespace

ConfinedIOSystem::ConfinedIOSystem(std::vector<fs::path> allowed_folders, fs::path base_folder,
                                   std::uintmax_t max_file_bytes)
    : allowed_(std::move(allowed_folders)),
      base_(std::move(base_folder)),
      max_file_bytes_(max_file_bytes) {}

ConfinedIOSystem::Checked ConfinedIOSystem::check(const char* file) const {
    Checked out;
    std::error_code ec;
    const fs::path written = file;
    out.resolved = fs::weakly_canonical(written.is_absolute() ? written : base_ / written, ec);
    if (ec) {
        out.why = "cannot be resolved: " + ec.message();
        return out;
    }
    for (const fs::path& folder : allowed_) {
        if (inside(out.resolved, folder)) return out;
    }
    out.why = "leads outside the folders a model may read from (";
    for (std::size_t i = 0; i < allowed_.size(); ++i) {
        out.why += (i ? ", " : "") + allowed_[i].string();
    }
    out.why += ")";
    return out;
}

void ConfinedIOSystem::refuse(const char* file, const std::string& why) const {
    if (refusal_.empty()) refusal_ = "reference '" + shown(file) + "': " + why;
}

bool ConfinedIOSystem::Exists(const char* file) const {
    if (!file) return false;
    const Checked c = check(file);
    if (!c.why.empty()) return false;
    std::error_code ec;
    return fs::exists(c.resolved, ec);
}

Assimp::IOStream* ConfinedIOSystem::Open(const char* file, const char* mode) {
    if (!file) return nullptr;
    if (mode && (std::string_view(mode).find_first_of("wa+") != std::string_view::npos)) {
        refuse(file, "opened for writing");
        return nullptr;
    }
    const Checked c = check(file);
    if (!c.why.empty()) {
        refuse(file, c.why);
        return nullptr;
    }
    RegularFileResult opened = open_regular_file(c.resolved);
    std::string why = opened.why;
    if (why.empty() && opened.file.size() > max_file_bytes_) {
        why = "is " + std::to_string(opened.file.size()) + " bytes, over the limit of " +
              std::to_string(max_file_bytes_);
    }
    if (!why.empty()) {
        // A missing file is the loader's business (it may be optional, like a default .mtl).
        if (why != "file not found") refuse(file, why);
        return nullptr;
    }
    const std::uintmax_t size = opened.file.size();
    const int fd = opened.file.release();
    std::FILE* f = ::fdopen(fd, "rb");
    if (!f) {
        ::close(fd);
        return nullptr;
    }
    return new FileStream(f, size);
}

void ConfinedIOSystem::Close(Assimp::IOStream* stream) {
    delete stream;
}

}  // namespace bz::geo::detail
