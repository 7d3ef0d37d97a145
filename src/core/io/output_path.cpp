#include "core/io/output_path.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <string>

#include "core/error.h"
#include "core/io/regular_file.h"
#include "core/text/printable.h"

namespace bz {

namespace fs = std::filesystem;

namespace {

fs::path folder_of(const fs::path& p) {
    return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

std::string quote(const fs::path& p) {
    return "'" + printable(p.string()) + "'";
}

[[noreturn]] void refuse(std::string_view option, const fs::path& out, const std::string& why) {
    throw UserError(std::string(option) + " " + quote(out) + ": " + why);
}

void require_folder(std::string_view option, const fs::path& out) {
    const fs::path dir = folder_of(out);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        refuse(option, out,
               "the folder " + quote(dir) + " does not exist (create it first; it is not " +
                   "created for you)");
    }
}

// Creates and removes a file in the folder: the one sure test that a write will be allowed
// (permissions, read-only mounts, /proc and /sys all answer here rather than at the end).
void probe_writable(std::string_view option, const fs::path& out) {
    const fs::path dir = folder_of(out);
    std::random_device rd;
    const fs::path probe = dir / (".beamzone-write-test-" + std::to_string(rd()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        refuse(option, out, "cannot create files in " + quote(dir) + ": " + std::strerror(errno));
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

// The first bytes of a regular file (at most `n`); opened only after stat said it is regular,
// so a FIFO or device at the path is never opened.
std::string head_of(const fs::path& p, std::size_t n) {
    std::string out(n, '\0');
    const int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) return {};
    std::size_t got = 0;
    while (got < n) {
        const ssize_t r = ::read(fd, out.data() + got, n - got);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) break;
        got += static_cast<std::size_t>(r);
    }
    ::close(fd);
    out.resize(got);
    return out;
}

}  // namespace

const OutputKind* output_kind_of(const fs::path& name) {
    const std::string ext = name.extension().string();
    if (ext == ".png") return &kPngOutput;
    if (ext == ".replay") return &kReplayOutput;
    if (ext == ".json") return &kJsonOutput;
    if (ext == ".csv") return &kCsvOutput;
    if (ext == ".svg") return &kSvgOutput;
    return nullptr;
}

void check_output_file(std::string_view option, const fs::path& out, const OutputKind& kind,
                       std::span<const fs::path> inputs, bool overwrite) {
    if (out.empty()) refuse(option, out, "an empty path");
    require_folder(option, out);
    std::error_code ec;
    const fs::file_status st = fs::status(out, ec);
    if (fs::exists(st)) {
        for (const fs::path& in : inputs) {
            std::error_code eq;
            // fs::equivalent compares device and inode of the final targets of both paths.
            if (!in.empty() && fs::equivalent(out, in, eq)) {
                refuse(option, out, "that is an input of this command (" + quote(in) + ")");
            }
        }
        if (fs::is_directory(st)) refuse(option, out, "that is a folder");
        if (!fs::is_regular_file(st)) {
            struct stat raw {};
            const std::string what = ::stat(out.c_str(), &raw) == 0
                                         ? describe_non_regular(raw.st_mode)
                                         : std::string("not a regular file");
            refuse(option, out, "that is " + what + ", not a regular file; it is never replaced");
        }
        const std::string head = head_of(out, kind.magic.size());
        if (!overwrite && !head.empty() && head != kind.magic) {
            refuse(option, out,
                   "an existing file that is not a " + std::string(kind.name) +
                       " is there; it is not replaced (remove it, or pass --overwrite)");
        }
    }
    probe_writable(option, out);
}

namespace {

// The files already in `dir` that carry an output's extension, each checked as an output.
void check_existing_outputs(std::string_view option, const fs::path& dir,
                            std::span<const fs::path> inputs, bool overwrite) {
    constexpr int kMaxEntries = 100000;  // a folder of millions of files is refused, not walked
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec) refuse(option, dir, "cannot list the folder: " + ec.message());
    int seen = 0;
    for (const fs::directory_entry& e : it) {
        if (++seen > kMaxEntries) refuse(option, dir, "the folder holds too many files");
        if (const OutputKind* kind = output_kind_of(e.path().filename())) {
            check_output_file(option, e.path(), *kind, inputs, overwrite);
        }
    }
}

}  // namespace

void check_output_dir(std::string_view option, const fs::path& out,
                      std::span<const fs::path> inputs,
                      std::span<const std::string_view> subfolders, bool overwrite) {
    if (out.empty()) refuse(option, out, "an empty path");
    require_folder(option, out);
    std::error_code ec;
    const fs::file_status st = fs::status(out, ec);
    if (!fs::exists(st)) {
        probe_writable(option, out);  // the folder will be created in its parent
        return;
    }
    if (!fs::is_directory(st))
        refuse(option, out, "an existing file that is not a folder is there");
    probe_writable(option, out / "x");
    check_existing_outputs(option, out, inputs, overwrite);
    for (const std::string_view sub : subfolders) {
        const fs::path p = out / sub;
        const fs::file_status sst = fs::status(p, ec);
        if (!fs::exists(sst)) continue;
        if (!fs::is_directory(sst))
            refuse(option, p, "an existing file that is not a folder is there");
        probe_writable(option, p / "x");
        check_existing_outputs(option, p, inputs, overwrite);
    }
}

}  // namespace bz
