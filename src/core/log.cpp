#include "core/log.h"

#include <chrono>
#include <ctime>

namespace bz {

Log::Log(const std::filesystem::path& file) : path_(file) {
    file_ = std::fopen(file.c_str(), "a");
}

Log::~Log() {
    if (file_) std::fclose(file_);
}

void Log::write(LogLevel level, std::string_view message) {
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
