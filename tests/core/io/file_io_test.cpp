#include "core/io/file_io.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;

TEST(FileIo, AtomicWriteReplacesWholeFile) {
    const bz::test::ScratchDir scratch("bz_file_io_test");
    const fs::path& dir = scratch.path();
    const fs::path f = dir / "a.txt";
    bz::write_file_atomic(f, "first");
    bz::write_file_atomic(f, "second version");
    EXPECT_EQ(bz::read_file(f), "second version");
    // No temp files are left behind.
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1);
}

TEST(FileIo, ReadRefusesMissingAndOversizedFiles) {
    EXPECT_THROW(bz::read_file("/nonexistent/file"), bz::UserError);
    EXPECT_THROW(bz::read_file("/dev/zero"), bz::UserError);  // not a regular file
    const bz::test::ScratchDir scratch("bz_big");
    const fs::path f = scratch.path() / "big.txt";
    bz::write_file_atomic(f, std::string(100, 'x'));
    EXPECT_THROW(bz::read_file(f, 10), bz::UserError);
}
