// Opening files that must be regular: FIFOs (which block a reader until a writer comes),
// devices and folders are refused at once, by what the descriptor is, not by a prior check.
#include "core/io/regular_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/io/file_io.h"
#include "support/scratch_dir.h"

namespace bz {
namespace {

namespace fs = std::filesystem;

using Scratch = bz::test::ScratchDir;

TEST(RegularFile, FifoIsRefusedWithoutBlocking) {
    Scratch s;
    const fs::path fifo = s.path() / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    const RegularFileResult r = open_regular_file(fifo);
    EXPECT_FALSE(r.file.is_open());
    EXPECT_EQ(r.why, "not a regular file (a FIFO)");
    // read_file, which the level loader, the watcher and the replay reader use, too.
    try {
        read_file(fifo);
        ADD_FAILURE() << "read a FIFO";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()), fifo.string() + ": not a regular file (a FIFO)");
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

TEST(RegularFile, DevicesFoldersAndMissingFilesAreNamed) {
    Scratch s;
    EXPECT_EQ(open_regular_file("/dev/zero").why, "not a regular file (a character device)");
    EXPECT_EQ(open_regular_file(s.path()).why, "not a regular file (a folder)");
    EXPECT_EQ(open_regular_file(s.path() / "nope").why, "file not found");
}

TEST(RegularFile, RegularFileOpensWithItsSizeAndReadsBlocking) {
    Scratch s;
    std::ofstream(s.path() / "f.txt") << "hello world";
    const RegularFileResult r = open_regular_file(s.path() / "f.txt");
    ASSERT_TRUE(r.file.is_open()) << r.why;
    EXPECT_EQ(r.file.size(), 11u);
    EXPECT_EQ(read_head(r.file, 5), "hello");
    EXPECT_EQ(read_head(r.file, 100), "hello world");
}

}  // namespace
}  // namespace bz
