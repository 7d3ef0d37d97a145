#include "core/io/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "core/error.h"
#include "core/io/regular_file.h"
#include "core/text/printable.h"

namespace bz {
namespace fs = std::filesystem;

std::string read_file(const fs::path& path, std::size_t max_bytes) {
    // Opened without blocking and checked on the descriptor: a FIFO or device swapped in
    // after a check by name can neither hang nor feed us endless bytes.
    RegularFileResult opened = open_regular_file(path);
    if (!opened.why.empty()) throw UserError(printable(path.string()) + ": " + opened.why);
    const std::uintmax_t size = opened.file.size();
    if (size > max_bytes) {
        throw UserError(printable(path.string()) + ": file is " + std::to_string(size) +
                        " bytes, over the limit of " + std::to_string(max_bytes));
    }
    return read_head(opened.file, static_cast<std::size_t>(size));
}

namespace {

void write_all(int fd, std::string_view bytes, const fs::path& path) {
    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            throw UserError(path.string() + ": write failed: " + std::strerror(errno));
        }
        p += n;
        left -= static_cast<std::size_t>(n);
    }
}

// A symbolic link (a dotfiles setup links settings.toml into a repository) is written
// through: the new file replaces the link's final target, and the link stays a link.
fs::path final_target(const fs::path& path) {
    constexpr int kMaxLinks = 40;  // as the kernel's ELOOP limit
    fs::path p = path;
    for (int i = 0; i < kMaxLinks; ++i) {
        std::error_code ec;
        if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
        const fs::path target = fs::read_symlink(p, ec);
        if (ec) throw UserError(path.string() + ": cannot read the link: " + ec.message());
        const fs::path base = p.has_parent_path() ? p.parent_path() : fs::path(".");
        p = target.is_absolute() ? target : base / target;
    }
    throw UserError(path.string() + ": too many levels of symbolic links");
}

}  // namespace

void write_file_atomic(const fs::path& requested, std::string_view bytes) {
    // The folder is never created here: a mistyped output path must fail, not grow folders.
    const fs::path path = final_target(requested);
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    // Whatever sits at the target must be a regular file: the rename below would replace a
    // device node, a FIFO or a socket with a plain file (as root, that destroys the node).
    struct stat old {};
    const bool replacing = ::stat(path.c_str(), &old) == 0;
    if (replacing && !S_ISREG(old.st_mode)) {
        throw UserError(printable(path.string()) + ": " + describe_non_regular(old.st_mode) +
                        " is there; it is never replaced");
    }
    std::random_device rd;
    const fs::path tmp = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd()));
    // A new file gets the usual 0666 less the umask; a replaced one keeps its mode and owner
    // (a settings.toml kept at 0600 must not become world-readable when the game saves it).
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw UserError(tmp.string() + ": cannot create: " + std::strerror(errno));
    try {
        if (replacing) {
            // The owner first: chown may clear set-id bits that fchmod then restores.
            // Changing the owner needs privilege; without it the file stays ours, which is
            // the same owner whenever we could write the old one in place.
            (void)::fchown(fd, old.st_uid, old.st_gid);
            if (::fchmod(fd, old.st_mode & 07777) != 0)
                throw UserError(tmp.string() + ": cannot set the mode: " + std::strerror(errno));
        }
        write_all(fd, bytes, tmp);
        if (::fsync(fd) != 0)
            throw UserError(tmp.string() + ": fsync failed: " + std::strerror(errno));
    } catch (...) {
        ::close(fd);
        ::unlink(tmp.c_str());
        throw;
    }
    ::close(fd);
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        ::unlink(tmp.c_str());
        throw UserError(path.string() + ": cannot replace: " + why);
    }
    // Make the rename itself durable.
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

}  // namespace bz
