#include "core/io/file_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <vector>

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

TEST(FileIo, AtomicWriteKeepsTheModeOfTheFileItReplaces) {
    const bz::test::ScratchDir scratch("bz_file_io_mode");
    const fs::path f = scratch.path() / "settings.toml";
    bz::write_file_atomic(f, "first");
    fs::permissions(f, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
    bz::write_file_atomic(f, "second");
    EXPECT_EQ(fs::status(f).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(bz::read_file(f), "second");
}

TEST(FileIo, AtomicWriteNeverReplacesAFileOfAnotherKind) {
    const bz::test::ScratchDir scratch("bz_file_io_kinds");
    const fs::path fifo = scratch.path() / "fifo";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    const fs::path dir = scratch.path() / "folder";
    fs::create_directory(dir);
    std::vector<fs::path> targets{fifo, dir};
    const fs::path dev = scratch.path() / "null";
    // A character device like /dev/null, made here when we may (as root).
    if (::mknod(dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) targets.push_back(dev);
    for (const fs::path& t : targets) {
        const fs::file_type before = fs::symlink_status(t).type();
        EXPECT_THROW(bz::write_file_atomic(t, "data"), bz::UserError) << t;
        EXPECT_EQ(fs::symlink_status(t).type(), before) << t;
    }
    // Through a link, too: the link's target is what would be replaced.
    const fs::path link = scratch.path() / "link";
    fs::create_symlink(fifo, link);
    EXPECT_THROW(bz::write_file_atomic(link, "data"), bz::UserError);
    EXPECT_EQ(fs::symlink_status(fifo).type(), fs::file_type::fifo);
}
