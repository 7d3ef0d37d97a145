#include "geometry/import/import_zip.h"

#include <minizip/unzip.h>
#include <unistd.h>

#include <cstdio>

namespace bz::geo::detail {
namespace {

// More entries than any model package has; also bounds the time spent listing.
constexpr std::uint64_t kMaxEntries = 65536;

// minizip opens by name; this opens a duplicate of an already checked descriptor instead, so
// the file read is the one that was checked (no second lookup of the path).
voidpf ZCALLBACK open_descriptor(voidpf opaque, const void*, int) {
    const int fd = ::dup(*static_cast<const int*>(opaque));
    if (fd < 0) return nullptr;
    std::FILE* f = ::fdopen(fd, "rb");
    if (!f) ::close(fd);
    return f;
}

class Archive {
  public:
    explicit Archive(int fd) : fd_(fd) {
        zlib_filefunc64_def io{};
        fill_fopen64_filefunc(&io);
        io.zopen64_file = open_descriptor;
        io.opaque = &fd_;
        handle_ = unzOpen2_64("", &io);
    }
    ~Archive() {
        if (handle_) unzClose(handle_);
    }
    Archive(const Archive&) = delete;
    Archive& operator=(const Archive&) = delete;
    unzFile get() const { return handle_; }

  private:
    int fd_;
    unzFile handle_ = nullptr;
};

}  // namespace

bool looks_like_zip(std::string_view head) {
    return head.substr(0, 4) == std::string_view("PK\x03\x04", 4) ||
           head.substr(0, 4) == std::string_view("PK\x05\x06", 4);
}

std::optional<std::string> zip_over_limits(int fd, std::uint64_t max_unzipped_bytes) {
    Archive zip(fd);
    if (!zip.get()) return "zip archive: its central directory cannot be read";
    std::uint64_t total = 0;
    std::uint64_t entries = 0;
    for (int at = unzGoToFirstFile(zip.get()); at == UNZ_OK; at = unzGoToNextFile(zip.get())) {
        if (++entries > kMaxEntries) {
            return "zip archive has more than " + std::to_string(kMaxEntries) + " entries";
        }
        unz_file_info64 info{};
        char name[256] = {};
        if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof name - 1, nullptr, 0, nullptr,
                                    0) != UNZ_OK) {
            return "zip archive: entry " + std::to_string(entries) + " cannot be read";
        }
        // The entry alone first, so the sum cannot overflow.
        const bool over = info.uncompressed_size > max_unzipped_bytes ||
                          total + info.uncompressed_size > max_unzipped_bytes;
        total += over ? 0 : info.uncompressed_size;
        if (over) {
            std::string shown;
            for (const char* c = name; *c && shown.size() < 80; ++c) {
                shown.push_back(*c >= 0x20 && *c < 0x7f ? *c : '?');
            }
            return "zip entry '" + shown + "' inflates to " +
                   std::to_string(info.uncompressed_size) + " bytes (after " +
                   std::to_string(total) + " in the entries before it), over the limit of " +
                   std::to_string(max_unzipped_bytes) + " uncompressed bytes";
        }
    }
    return std::nullopt;
}

}  // namespace bz::geo::detail
