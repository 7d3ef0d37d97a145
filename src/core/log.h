#pragma once
// Logging: every line goes to stderr, and to the log file once one is opened (the game opens
// one under the pref path). The sink is owned by a Log object, not a global.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string_view>

namespace bz {

enum class LogLevel { debug, info, warn, error };

class Log {
  public:
    Log() = default;
    explicit Log(const std::filesystem::path& file);
    ~Log();
    Log(const Log&) = delete;
    Log& operator=(const Log&) = delete;

    void write(LogLevel level, std::string_view message);
    void info(std::string_view m) { write(LogLevel::info, m); }
    void warn(std::string_view m) { write(LogLevel::warn, m); }
    void error(std::string_view m) { write(LogLevel::error, m); }
    const std::filesystem::path& file_path() const { return path_; }
    void set_verbose(bool v) { verbose_ = v; }

  private:
    std::filesystem::path path_;
    std::FILE* file_ = nullptr;
    bool verbose_ = false;
};

}  // namespace bz
