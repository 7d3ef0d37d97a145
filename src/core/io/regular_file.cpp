#include "core/io/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace bz {

struct RegularFileOpener {
    static RegularFile make(int fd, std::uintmax_t size) {
        RegularFile f;
        f.fd_ = fd;
        f.size_ = size;
        return f;
    }
};

std::string describe_non_regular(unsigned mode_bits) {
    const auto mode = static_cast<mode_t>(mode_bits);
    if (S_ISDIR(mode)) return "a folder";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a plain file";
}

RegularFile::RegularFile(RegularFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), size_(other.size_) {}

RegularFile& RegularFile::operator=(RegularFile&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
        size_ = other.size_;
    }
    return *this;
}

RegularFile::~RegularFile() {
    if (fd_ >= 0) ::close(fd_);
}

int RegularFile::release() {
    return std::exchange(fd_, -1);
}

RegularFileResult open_regular_file(const std::filesystem::path& path) {
    RegularFileResult out;
    // O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting forever.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        const int err = errno;
        out.why = (err == ENOENT || err == ENOTDIR)
                      ? std::string("file not found")
                      : std::string("cannot open: ") + std::strerror(err);
        return out;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        out.why = std::string("cannot stat: ") + std::strerror(errno);
        ::close(fd);
        return out;
    }
    if (!S_ISREG(st.st_mode)) {
        out.why = "not a regular file (" + describe_non_regular(st.st_mode) + ")";
        ::close(fd);
        return out;
    }
    // A regular file never blocks, but readers may treat EAGAIN as an error: clear the flag.
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    out.file = RegularFileOpener::make(fd, static_cast<std::uintmax_t>(st.st_size));
    return out;
}

std::string read_head(const RegularFile& file, std::size_t max_bytes) {
    std::string head;
    if (!file.is_open()) return head;
    head.resize(static_cast<std::size_t>(std::min<std::uintmax_t>(max_bytes, file.size())));
    std::size_t got = 0;
    while (got < head.size()) {
        const ssize_t n =
            ::pread(file.fd(), head.data() + got, head.size() - got, static_cast<off_t>(got));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += static_cast<std::size_t>(n);
    }
    head.resize(got);
    return head;
}

}  // namespace bz
