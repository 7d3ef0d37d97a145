// Hot reload: a broken save keeps the last good level and reports the error with its
// position; fixing the file brings the new level in.
#include "level/watcher.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/io/file_io.h"
#include "level_test_util.h"

namespace bz::level {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

std::string named(const std::string& name, const std::string& body = "") {
    return "version = 1\nname = \"" + name + "\"\n" + body;
}

LoadOptions options_for(const ScratchDir& dir) {
    LoadOptions o;
    o.data_root = dir.path() / "data";
    return o;
}

TEST(LevelWatcher, BrokenSaveKeepsTheOldLevelAndReportsTheError) {
    ScratchDir dir;
    const fs::path file = dir.write("level.toml", named("Good"));
    LevelWatcher watcher(file, options_for(dir));
    ASSERT_TRUE(watcher.current());
    EXPECT_EQ(watcher.current()->name, "Good");
    EXPECT_TRUE(watcher.errors().empty());
    EXPECT_EQ(watcher.generation(), 1u);
    EXPECT_FALSE(watcher.poll());

    // The way editors save: a new file renamed over the old one.
    write_file_atomic(file, named("Broken", "[field]\nsize = \n"));
    EXPECT_TRUE(watcher.poll());
    ASSERT_TRUE(watcher.current());
    EXPECT_EQ(watcher.current()->name, "Good");
    EXPECT_EQ(watcher.generation(), 1u);
    ASSERT_EQ(watcher.errors().size(), 1u);
    EXPECT_EQ(watcher.errors()[0].pos.line, 4);
    EXPECT_EQ(watcher.errors()[0].pos.column, 8);  // the newline after "size = "
    EXPECT_EQ(format(watcher.errors()[0]).rfind(file.string() + ":4:8: error: syntax error", 0),
              0u);
    EXPECT_FALSE(watcher.poll());  // nothing changed since
    EXPECT_EQ(watcher.errors().size(), 1u);

    write_file_atomic(file, named("Fixed", "[field]\nsize = 300\n"));
    EXPECT_TRUE(watcher.poll());
    ASSERT_TRUE(watcher.current());
    EXPECT_EQ(watcher.current()->name, "Fixed");
    EXPECT_EQ(watcher.current()->field_size, 300.0);
    EXPECT_TRUE(watcher.errors().empty());
    EXPECT_EQ(watcher.generation(), 2u);
}

TEST(LevelWatcher, InPlaceWriteOfTheSameSizeIsNoticed) {
    ScratchDir dir;
    const fs::path file = dir.write("level.toml", named("AAAA"));
    LevelWatcher watcher(file, options_for(dir));
    // Same size, same inode: only the modification time can tell. Set it explicitly so the
    // test does not depend on the file system's timestamp granularity.
    dir.write("level.toml", named("BBBB"));
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
    EXPECT_TRUE(watcher.poll());
    EXPECT_EQ(watcher.current()->name, "BBBB");
}

TEST(LevelWatcher, ModelFileChangesAndAppearancesTriggerAReload) {
    ScratchDir dir;
    const std::string body =
        "[[obstacle]]\nkind = \"model\"\nmodel = \"dish.obj\"\nposition = [50, 0, 0]\n";
    const fs::path file = dir.write("level.toml", named("Models", body));
    LevelWatcher watcher(file, options_for(dir));
    EXPECT_FALSE(watcher.current());
    ASSERT_EQ(watcher.errors().size(), 1u);
    EXPECT_EQ(watcher.errors()[0].pos.line, 5);
    EXPECT_NE(watcher.errors()[0].message.find("not found"), std::string::npos);

    // Creating the missing model fixes the level without touching the level file.
    write_file_atomic(dir.path() / "dish.obj", "v 0 0 0\n");
    EXPECT_TRUE(watcher.poll());
    ASSERT_TRUE(watcher.current());
    EXPECT_EQ(watcher.generation(), 1u);

    // Editing the model gives the game a new generation to re-import it.
    write_file_atomic(dir.path() / "dish.obj", "v 0 0 0\nv 1 0 0\n");
    EXPECT_TRUE(watcher.poll());
    EXPECT_EQ(watcher.generation(), 2u);
    EXPECT_EQ(watcher.watched().size(), 2u);
}

TEST(LevelWatcher, DeletedFileKeepsTheLevelUntilItComesBack) {
    ScratchDir dir;
    const fs::path file = dir.write("level.toml", named("Here"));
    LevelWatcher watcher(file, options_for(dir));
    fs::remove(file);
    EXPECT_TRUE(watcher.poll());
    ASSERT_TRUE(watcher.current());
    EXPECT_EQ(watcher.current()->name, "Here");
    ASSERT_EQ(watcher.errors().size(), 1u);
    EXPECT_NE(watcher.errors()[0].message.find("not found"), std::string::npos);
    dir.write("level.toml", named("Back"));
    EXPECT_TRUE(watcher.poll());
    EXPECT_EQ(watcher.current()->name, "Back");
    EXPECT_TRUE(watcher.errors().empty());
}

TEST(LevelWatcher, FirstLoadFailingLeavesNoLevel) {
    ScratchDir dir;
    const fs::path file = dir.write("level.toml", "version = 1\n");
    LevelWatcher watcher(file, options_for(dir));
    EXPECT_FALSE(watcher.current());
    EXPECT_EQ(watcher.generation(), 0u);
    ASSERT_EQ(watcher.errors().size(), 1u);
    EXPECT_NE(watcher.errors()[0].message.find("needs the key 'name'"), std::string::npos);
}

}  // namespace
}  // namespace bz::level
