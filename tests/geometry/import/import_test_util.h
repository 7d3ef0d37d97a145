#pragma once
// Scratch folders and error capture for the import tests (crafted files are written per test
// process, since ctest runs tests in parallel).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "geometry/import/import.h"

namespace bz::geo::test {

class ScratchDir {
  public:
    ScratchDir() {
        static std::atomic<int> serial{0};
        path_ = std::filesystem::temp_directory_path() /
                ("bz_import_" + std::to_string(::getpid()) + "_" + std::to_string(serial++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
        path_ = std::filesystem::canonical(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }

    std::filesystem::path write(const std::string& name, const std::string& bytes) const {
        const std::filesystem::path p = path_ / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }

    std::filesystem::path fifo(const std::string& name) const {
        const std::filesystem::path p = path_ / name;
        std::filesystem::create_directories(p.parent_path());
        EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
        return p;
    }

  private:
    std::filesystem::path path_;
};

// Imports expecting a UserError; returns its message (and fails the test when there is none).
inline std::string import_error(const std::filesystem::path& path,
                                const ImportOptions& options = {}) {
    try {
        import_model(path, options);
    } catch (const UserError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no UserError for " << path;
    return {};
}

// A one-line message that starts with the file's name and contains `reason`.
inline void expect_refusal(const std::string& message, const std::filesystem::path& path,
                           const std::string& reason) {
    EXPECT_EQ(message.rfind(path.string() + ": error: ", 0), 0u) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

// Options with a short deadline, so that a test whose defence fails ends quickly and says
// "took more than" instead of hanging.
inline ImportOptions quick(ImportOptions o = {}) {
    o.limits.seconds = 5.0;
    return o;
}

}  // namespace bz::geo::test
