#include "geometry/import/import_worker.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "geometry/import/import_failure.h"

#if defined(__SANITIZE_ADDRESS__)
#define BZ_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BZ_ADDRESS_SANITIZER 1
#endif
#endif

namespace bz::geo::detail {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// What the child sends: one frame, a kind byte and two counts, then the payload.
enum class Frame : char { mesh = 'M', error = 'E', out_of_memory = 'O' };
struct FrameHeader {
    char kind = 0;
    std::uint64_t a = 0;  // mesh: positions; error: message bytes
    std::uint64_t b = 0;  // mesh: indices (then b / 3 face materials)
};
constexpr std::size_t kHeaderBytes = 1 + 8 + 8;
// How often the parent looks at the child's resident memory.
constexpr int kWatchMilliseconds = 20;
constexpr std::size_t kMaxMessageBytes = 4096;

bool write_all(int fd, const void* data, std::size_t bytes) {
    const auto* p = static_cast<const char*>(data);
    while (bytes > 0) {
        const ssize_t n = ::write(fd, p, bytes);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        bytes -= static_cast<std::size_t>(n);
    }
    return true;
}

void send_header(int fd, Frame kind, std::uint64_t a, std::uint64_t b) {
    char h[kHeaderBytes];
    h[0] = static_cast<char>(kind);
    std::memcpy(h + 1, &a, 8);
    std::memcpy(h + 9, &b, 8);
    write_all(fd, h, sizeof h);
}

void send_text(int fd, Frame kind, const std::string& text) {
    const std::string cut = text.substr(0, kMaxMessageBytes);
    send_header(fd, kind, cut.size(), 0);
    write_all(fd, cut.data(), cut.size());
}

void cap_child_memory(std::uint64_t bytes) {
    rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);  // a crashing import must not write gigabytes of core
#if !defined(BZ_ADDRESS_SANITIZER)
    // ASan maps its shadow memory and allocator arenas up front, which a data-segment cap
    // would starve; sanitizer builds rely on the parent's resident-size watch alone.
    if (bytes == 0) return;
    rlimit current{};
    if (getrlimit(RLIMIT_DATA, &current) != 0) return;
    if (current.rlim_cur != RLIM_INFINITY && current.rlim_cur <= bytes) return;
    rlimit next = current;
    next.rlim_cur = static_cast<rlim_t>(bytes);
    setrlimit(RLIMIT_DATA, &next);
#else
    (void)bytes;
#endif
}

[[noreturn]] void child_main(int out, pid_t parent, const fs::path& path,
                             const ImportLimits& limits, const std::function<TriMesh()>& work) {
    // Die with the parent, and let Ctrl-C and SIGTERM end the child whatever handlers the
    // parent installed.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(3);
    // A crash in the importer is reported by the parent from the signal; the handlers of
    // sanitizers and fuzzers would only print a report nobody reads (stderr is captured).
    for (const int sig : {SIGINT, SIGTERM, SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
        std::signal(sig, SIG_DFL);
    }
    cap_child_memory(limits.memory_bytes);
    try {
        const TriMesh mesh = work();
        send_header(out, Frame::mesh, mesh.positions.size(), mesh.indices.size());
        write_all(out, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
        write_all(out, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
        // One material per triangle follows the indices (zeros when the mesh has none).
        std::vector<std::uint32_t> materials = mesh.face_materials;
        materials.resize(mesh.triangle_count(), 0);
        write_all(out, materials.data(), materials.size() * sizeof(std::uint32_t));
    } catch (const UserError& e) {
        send_text(out, Frame::error, e.what());
    } catch (const std::bad_alloc&) {
        send_text(out, Frame::out_of_memory, "");
    } catch (const std::exception& e) {
        send_text(out, Frame::error, path.string() + ": error: import failed: " + e.what());
    } catch (...) {
        send_text(out, Frame::error, path.string() + ": error: import failed");
    }
    _exit(0);  // no atexit handlers, no stdio flush, no destructors of the parent's objects
}

std::uint64_t resident_bytes(pid_t pid) {
    char name[64];
    std::snprintf(name, sizeof name, "/proc/%d/statm", static_cast<int>(pid));
    std::FILE* f = std::fopen(name, "re");
    if (!f) return 0;
    unsigned long long size = 0, resident = 0;
    const int n = std::fscanf(f, "%llu %llu", &size, &resident);
    std::fclose(f);
    if (n != 2) return 0;
    return resident * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

// CPU time the process has used (user + system), in seconds; 0 when it cannot be read.
double cpu_seconds(pid_t pid) {
    char name[64];
    std::snprintf(name, sizeof name, "/proc/%d/stat", static_cast<int>(pid));
    std::FILE* f = std::fopen(name, "re");
    if (!f) return 0.0;
    char line[1024];
    const bool got = std::fgets(line, sizeof line, f) != nullptr;
    std::fclose(f);
    if (!got) return 0.0;
    // The command name (field 2) may hold spaces and ')': the fields after it start after
    // the last ')'. utime and stime are fields 14 and 15, the 12th and 13th after it.
    const char* rest = std::strrchr(line, ')');
    if (!rest) return 0.0;
    unsigned long long utime = 0, stime = 0;
    if (std::sscanf(rest + 1, " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &utime,
                    &stime) != 2) {
        return 0.0;
    }
    return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

std::string megabytes(std::uint64_t bytes) {
    return std::to_string(bytes >> 20) + " MB";
}

// Reads the child's one frame as it arrives: the header, then straight into the mesh.
class Receiver {
  public:
    explicit Receiver(const ImportLimits& limits) : limits_(limits) {}

    // Takes bytes from the pipe; false when the frame is malformed (the child is ours, but a
    // broken child must not make the parent allocate without bound).
    bool take(const char* data, std::size_t n) {
        while (n > 0) {
            if (header_got_ < kHeaderBytes) {
                const std::size_t k = std::min(n, kHeaderBytes - header_got_);
                std::memcpy(header_ + header_got_, data, k);
                header_got_ += k;
                data += k;
                n -= k;
                if (header_got_ == kHeaderBytes && !start()) return false;
                continue;
            }
            if (segment_ >= segments_.size()) return false;  // more than the frame said
            auto& [ptr, left] = segments_[segment_];
            const std::size_t k = std::min(n, left);
            std::memcpy(ptr, data, k);
            ptr += k;
            left -= k;
            data += k;
            n -= k;
            if (left == 0) ++segment_;
        }
        return true;
    }

    bool complete() const { return header_got_ == kHeaderBytes && segment_ == segments_.size(); }
    Frame kind() const { return static_cast<Frame>(header_[0]); }
    TriMesh& mesh() { return mesh_; }
    const std::string& text() const { return text_; }

  private:
    bool start() {
        std::uint64_t a = 0, b = 0;
        std::memcpy(&a, header_ + 1, 8);
        std::memcpy(&b, header_ + 9, 8);
        switch (kind()) {
            case Frame::mesh:
                if (a > limits_.max_triangles * 3 || b > limits_.max_triangles * 3 || b % 3) {
                    return false;
                }
                mesh_.positions.resize(a);
                mesh_.indices.resize(b);
                add(reinterpret_cast<char*>(mesh_.positions.data()), a * sizeof(glm::vec3));
                add(reinterpret_cast<char*>(mesh_.indices.data()), b * sizeof(std::uint32_t));
                mesh_.face_materials.resize(b / 3);
                add(reinterpret_cast<char*>(mesh_.face_materials.data()),
                    b / 3 * sizeof(std::uint32_t));
                return true;
            case Frame::error:
            case Frame::out_of_memory:
                if (a > kMaxMessageBytes) return false;
                text_.resize(a);
                add(text_.data(), a);
                return true;
        }
        return false;
    }
    void add(char* p, std::size_t bytes) {
        if (bytes > 0) segments_.push_back({p, bytes});
    }

    const ImportLimits& limits_;
    char header_[kHeaderBytes] = {};
    std::size_t header_got_ = 0;
    std::vector<std::pair<char*, std::size_t>> segments_;
    std::size_t segment_ = 0;
    TriMesh mesh_;
    std::string text_;
};

// Owns the child until it has been waited for, so no exit path leaves a zombie or a runaway.
class Child {
  public:
    explicit Child(pid_t pid) : pid_(pid) {}
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;
    ~Child() {
        if (pid_ > 0) {
            ::kill(pid_, SIGKILL);
            wait_blocking();
        }
    }
    pid_t pid() const { return pid_; }
    void kill_now() { ::kill(pid_, SIGKILL); }
    // Waits for the child; returns its wait status.
    int wait_blocking() {
        int status = 0;
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
        pid_ = -1;
        return status;
    }
    // Waits until the deadline at most; nullopt when the child is still running then.
    std::optional<int> wait_until(Clock::time_point deadline) {
        // A pidfd becomes readable when the child exits: no polling interval to wait out.
        const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
        if (pidfd >= 0) {
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
            pollfd p{pidfd, POLLIN, 0};
            ::poll(&p, 1, static_cast<int>(std::max<long long>(left.count(), 0)));
            ::close(pidfd);
        }
        for (;;) {
            int status = 0;
            const pid_t r = ::waitpid(pid_, &status, WNOHANG);
            if (r == pid_) {
                pid_ = -1;
                return status;
            }
            if (r < 0 && errno != EINTR) {
                pid_ = -1;
                return 0;
            }
            if (Clock::now() >= deadline) return std::nullopt;
            ::usleep(2000);
        }
    }

  private:
    pid_t pid_;
};

std::string signal_text(int sig) {
    const char* name = sigabbrev_np(sig);
    const char* what = strsignal(sig);
    return std::string("SIG") + (name ? name : std::to_string(sig).c_str()) + ", " +
           (what ? what : "unknown signal");
}

}  // namespace

TriMesh run_isolated(const fs::path& path, const ImportLimits& limits,
                     const std::function<TriMesh()>& work) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        fail_import(path, std::string("cannot create a pipe: ") + std::strerror(errno));
    const pid_t parent = ::getpid();
    std::fflush(nullptr);  // buffered output is written once, not once per process
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int err = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        fail_import(path, std::string("cannot start the import process: ") + std::strerror(err));
    }
    if (pid == 0) {
        ::close(fds[0]);
        child_main(fds[1], parent, path, limits, work);
    }
    ::close(fds[1]);
    Child child(pid);
    struct Pipe {
        int fd;
        ~Pipe() { ::close(fd); }
    } in{fds[0]};

    const auto start = Clock::now();
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(limits.wall_seconds));
    const std::string wall_abandoned = "import did not finish within " +
                                       seconds_text(limits.wall_seconds) +
                                       " s (blocked, or the machine too busy) and was abandoned";
    Receiver receiver(limits);
    std::vector<char> buf(1 << 16);
    for (;;) {
        const auto now = Clock::now();
        if (now >= deadline) {
            child.kill_now();
            fail_import(path, wall_abandoned);
        }
        if (cpu_seconds(child.pid()) > limits.seconds) {
            child.kill_now();
            fail_import(path, "import took more than " + seconds_text(limits.seconds) +
                                  " s of CPU time and was abandoned");
        }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now);
        pollfd p{in.fd, POLLIN, 0};
        const int ready = ::poll(
            &p, 1, static_cast<int>(std::min<long long>(left.count() + 1, kWatchMilliseconds)));
        if (ready < 0 && errno == EINTR) {
            // SIGINT or SIGTERM: the command is ending; do not make it wait for the import.
            child.kill_now();
            fail_import(path, "import interrupted by a signal");
        }
        if (limits.memory_bytes > 0 && resident_bytes(child.pid()) > limits.memory_bytes) {
            child.kill_now();
            fail_import(path,
                        "import needed more than " + megabytes(limits.memory_bytes) +
                            " of memory (the cap, BEAMZONE_MEMORY_LIMIT_MB) and was abandoned");
        }
        if (ready <= 0) continue;
        const ssize_t n = ::read(in.fd, buf.data(), buf.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // end of file: the child is done (or died)
        if (!receiver.take(buf.data(), static_cast<std::size_t>(n))) {
            child.kill_now();
            fail_import(path, "the import process sent a malformed result");
        }
    }
    const std::optional<int> status = child.wait_until(deadline + std::chrono::seconds(1));
    if (!status) {
        child.kill_now();
        fail_import(path, wall_abandoned);
    }
    if (WIFSIGNALED(*status)) {
        const int sig = WTERMSIG(*status);
        if (sig == SIGKILL) {
            fail_import(path, "the import process was killed (SIGKILL; out of memory?)");
        }
        fail_import(path, "the importer crashed on this file (" + signal_text(sig) + ")");
    }
    if (!receiver.complete()) {
        fail_import(path, "the import process ended without a result (exit status " +
                              std::to_string(WIFEXITED(*status) ? WEXITSTATUS(*status) : -1) + ")");
    }
    switch (receiver.kind()) {
        case Frame::mesh: {
            TriMesh& mesh = receiver.mesh();
            for (const std::uint32_t i : mesh.indices) {
                if (i >= mesh.positions.size())
                    fail_import(path, "the import process sent a malformed result");
            }
            return std::move(mesh);
        }
        case Frame::error:
            throw UserError(receiver.text());
        case Frame::out_of_memory:
            if (limits.memory_bytes == 0) fail_import(path, "import ran out of memory");
            fail_import(path, "import needed more than " + megabytes(limits.memory_bytes) +
                                  " of memory (the cap, BEAMZONE_MEMORY_LIMIT_MB)");
    }
    fail_import(path, "the import process sent a malformed result");
}

}  // namespace bz::geo::detail
