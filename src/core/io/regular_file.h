#pragma once
// Opening a file that must be a plain regular file, without ever blocking on one that is not.
// open(2) on a FIFO waits for a writer and reading a device may never end, so a path is
// opened with O_NONBLOCK, checked with fstat on the descriptor itself (no race between a
// check and the open), and only then made blocking again.
#include <cstdint>
#include <filesystem>
#include <string>

namespace bz {

// An open, read-only descriptor of a regular file; closes it when destroyed.
class RegularFile {
  public:
    RegularFile() = default;
    RegularFile(RegularFile&& other) noexcept;
    RegularFile& operator=(RegularFile&& other) noexcept;
    RegularFile(const RegularFile&) = delete;
    RegularFile& operator=(const RegularFile&) = delete;
    ~RegularFile();

    bool is_open() const { return fd_ >= 0; }
    int fd() const { return fd_; }
    std::uintmax_t size() const { return size_; }
    // Gives the descriptor away (to fdopen and the like); the caller closes it.
    int release();

  private:
    friend struct RegularFileOpener;
    int fd_ = -1;
    std::uintmax_t size_ = 0;
};

struct RegularFileResult {
    RegularFile file;  // open when `why` is empty
    std::string why;   // "file not found", "not a regular file (a FIFO)", ...
};

// What a file that is not a regular one is, for messages: "a FIFO", "a character device"...
// (`mode_bits` is a stat st_mode).
std::string describe_non_regular(unsigned mode_bits);

// Opens `path` for reading when it names a regular file (symbolic links followed).
RegularFileResult open_regular_file(const std::filesystem::path& path);

// Reads up to `max_bytes` from the start of an open file (fewer when it is shorter).
std::string read_head(const RegularFile& file, std::size_t max_bytes);

}  // namespace bz
