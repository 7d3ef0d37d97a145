// Atomic writes onto a symbolic link (a dotfiles setup links settings.toml into a repository):
// the link stays a link and its target gets the new content; a chain of links is followed, a
// loop is an error, and nothing is created in a folder that does not exist.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "core/io/file_io.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;

namespace {

// A scratch folder with an empty dotfiles/ folder in it.
struct TempDir : bz::test::ScratchDir {
    TempDir() : ScratchDir("bz_links") { fs::create_directories(path() / "dotfiles"); }
};

TEST(AtomicWriteThroughLinks, RelativeLinkKeepsBeingALink) {
    TempDir t;
    bz::write_file_atomic(t.path() / "dotfiles" / "settings.toml", "old");
    fs::create_symlink("dotfiles/settings.toml", t.path() / "settings.toml");
    bz::write_file_atomic(t.path() / "settings.toml", "new");
    EXPECT_TRUE(fs::is_symlink(t.path() / "settings.toml"));
    EXPECT_EQ(bz::read_file(t.path() / "dotfiles" / "settings.toml"), "new");
    EXPECT_EQ(bz::read_file(t.path() / "settings.toml"), "new");
}

TEST(AtomicWriteThroughLinks, ChainsAndDanglingLinksReachTheFinalTarget) {
    TempDir t;
    // dangling, absolute
    fs::create_symlink(t.path() / "dotfiles" / "real.toml", t.path() / "b");
    fs::create_symlink("b", t.path() / "a");
    bz::write_file_atomic(t.path() / "a", "made");
    EXPECT_TRUE(fs::is_symlink(t.path() / "a"));
    EXPECT_TRUE(fs::is_symlink(t.path() / "b"));
    EXPECT_EQ(bz::read_file(t.path() / "dotfiles" / "real.toml"), "made");
}

TEST(AtomicWriteThroughLinks, LinkLoopIsAnError) {
    TempDir t;
    fs::create_symlink("y", t.path() / "x");
    fs::create_symlink("x", t.path() / "y");
    EXPECT_THROW(bz::write_file_atomic(t.path() / "x", "loop"), bz::UserError);
    EXPECT_TRUE(fs::is_symlink(t.path() / "x"));
}

TEST(AtomicWriteMissingFolder, FolderIsNotCreated) {
    TempDir t;
    EXPECT_THROW(bz::write_file_atomic(t.path() / "no" / "such" / "f.txt", "x"), bz::UserError);
    EXPECT_FALSE(fs::exists(t.path() / "no"));
}

}  // namespace
