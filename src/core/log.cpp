#include "core/log.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <ctime>

#include "core/text/printable.h"

namespace bz {

Log::Log(const std::filesystem::path& file) : path_(file) {
    // Opened without blocking and checked on the descriptor: a FIFO at the log's path would
    // block fopen forever, and a device is no log. Either way the game runs without a log.
    const int fd = ::open(file.c_str(),
                          O_WRONLY | O_APPEND | O_CREAT | O_NONBLOCK | O_CLOEXEC | O_NOCTTY, 0666);
    if (fd < 0) return;
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return;
    }
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    file_ = ::fdopen(fd, "a");
    if (!file_) ::close(fd);
}

Log::~Log() {
    if (file_) std::fclose(file_);
}

void Log::write(LogLevel level, std::string_view raw) {
    // Log lines carry paths, level names and SDL's words: no escape, bidi override or newline
    // passes (one record is one line, which no value can split to forge another).
    // A record is cut at 4 KB: enough for any real message, not for a 100 KB argument.
    const std::string safe = printable(raw, 4096);
    const std::string_view message = safe;
    static constexpr const char* kNames[] = {"debug", "info", "warn", "error"};
    const char* name = kNames[static_cast<int>(level)];
    if (level != LogLevel::debug || verbose_) {
        std::fprintf(stderr, "beamzone: %s: %.*s\n", name, static_cast<int>(message.size()),
                     message.data());
    }
    if (file_) {
        const std::time_t now =
            std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
        char stamp[32];
        std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
        std::fprintf(file_, "%s %s: %.*s\n", stamp, name, static_cast<int>(message.size()),
                     message.data());
        std::fflush(file_);
    }
}

}  // namespace bz
