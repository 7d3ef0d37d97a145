#pragma once
// Scratch folders and error capture for the import tests (crafted files are written per test
// process, since ctest runs tests in parallel).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "geometry/import/import.h"
#include "support/scratch_dir.h"

namespace bz::geo::test {

using ScratchDir = bz::test::ScratchDir;

// Makes a FIFO at `name` under the folder: a file whose reader would block for ever.
inline std::filesystem::path make_fifo(const ScratchDir& dir, const std::string& name) {
    const std::filesystem::path p = dir.path() / name;
    std::filesystem::create_directories(p.parent_path());
    EXPECT_EQ(::mkfifo(p.c_str(), 0600), 0);
    return p;
}

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

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Options with a short deadline, so that a test whose defence fails ends quickly and says
// "took more than" instead of hanging.
inline ImportOptions quick(ImportOptions o = {}) {
    o.limits.seconds = 5.0;
    return o;
}

}  // namespace bz::geo::test
