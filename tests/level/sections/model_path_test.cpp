// Model paths: resolved next to the level file, confined to the level's folder or data/.
#include "level/sections/model_path.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "level/level_test_util.h"
#include "level/loader.h"

namespace bz::level {
namespace {

namespace fs = std::filesystem;
using test::has_one_error;
using test::level_text;
using test::ScratchDir;

// scratch/levels/test.toml with scratch/data as the data root.
class ModelPaths : public ::testing::Test {
  protected:
    ScratchDir dir;
    LoadResult load_with_model(const std::string& model, const std::string& extra = "") {
        const std::string text = level_text("[[obstacle]]\nkind = \"model\"\nmodel = \"" + model +
                                            "\"\nposition = [50, 0, 0]\n" + extra);
        const fs::path file = dir.write("levels/test.toml", text);
        LoadOptions options;
        options.data_root = dir.path() / "data";
        return load_level_file(file, options);
    }
};

TEST_F(ModelPaths, ResolvesNextToTheLevelFile) {
    dir.write("levels/models/dish.obj", "v 0 0 0\n");
    const auto r = load_with_model("models/dish.obj");
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    EXPECT_EQ(r.level->obstacles[0].model, dir.path() / "levels/models/dish.obj");
    EXPECT_EQ(r.level->obstacles[0].footprint_radius, 3.0);
    ASSERT_EQ(r.dependencies.size(), 2u);
    EXPECT_EQ(r.dependencies[1], dir.path() / "levels/models/dish.obj");
}

TEST_F(ModelPaths, MayReachIntoData) {
    dir.write("data/models/pylon.obj", "v 0 0 0\n");
    const auto r = load_with_model("../data/models/pylon.obj", "radius = 2\nscale = 3\n");
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    EXPECT_EQ(r.level->obstacles[0].model, dir.path() / "data/models/pylon.obj");
    EXPECT_EQ(r.level->obstacles[0].footprint_radius, 6.0);
}

TEST_F(ModelPaths, DotDotOutOfBothFoldersIsRefused) {
    dir.write("secret.obj", "v 0 0 0\n");
    const auto r = load_with_model("../secret.obj");
    EXPECT_TRUE(
        has_one_error(r, 5, 9, "leads outside the level's folder and the project's data/ folder"));
}

TEST_F(ModelPaths, DotDotThatStaysInsideIsFine) {
    dir.write("levels/models/dish.obj", "v 0 0 0\n");
    EXPECT_TRUE(load_with_model("models/../models/./dish.obj").ok());
}

TEST_F(ModelPaths, AbsolutePathIsRefused) {
    dir.write("data/models/pylon.obj", "v 0 0 0\n");
    const auto r = load_with_model((dir.path() / "data/models/pylon.obj").string());
    EXPECT_TRUE(has_one_error(r, 5, 9, "is absolute; write it relative to the level file"));
}

TEST_F(ModelPaths, SymlinkOutIsRefused) {
    dir.write("outside/secret.obj", "v 0 0 0\n");
    fs::create_directories(dir.path() / "levels");
    fs::create_directory_symlink(dir.path() / "outside", dir.path() / "levels/linked");
    const auto r = load_with_model("linked/secret.obj");
    EXPECT_TRUE(has_one_error(r, 5, 9, "leads outside"));
}

TEST_F(ModelPaths, SymlinkedFileOutIsRefused) {
    dir.write("outside/secret.obj", "v 0 0 0\n");
    fs::create_directories(dir.path() / "levels");
    fs::create_symlink(dir.path() / "outside/secret.obj", dir.path() / "levels/innocent.obj");
    EXPECT_TRUE(has_one_error(load_with_model("innocent.obj"), 5, 9, "leads outside"));
}

TEST_F(ModelPaths, MissingFileIsReportedAndStillWatched) {
    const auto r = load_with_model("models/later.obj");
    EXPECT_TRUE(has_one_error(r, 5, 9, "model file 'models/later.obj' not found"));
    // A watcher must notice when the author creates it.
    ASSERT_EQ(r.dependencies.size(), 2u);
    EXPECT_EQ(r.dependencies[1], dir.path() / "levels/models/later.obj");
}

TEST_F(ModelPaths, DirectoryAndUnknownExtensionAreRefused) {
    fs::create_directories(dir.path() / "levels/models/dir.obj");
    EXPECT_TRUE(has_one_error(load_with_model("models/dir.obj"), 5, 9, "is not a regular file"));
    dir.write("levels/models/notes.txt", "hi");
    EXPECT_TRUE(has_one_error(load_with_model("models/notes.txt"), 5, 9, "unsupported extension"));
}

TEST_F(ModelPaths, ModelKindNeedsAModel) {
    const fs::path file =
        dir.write("levels/test.toml", level_text("[[obstacle]]\nkind = \"model\"\n"
                                                 "position = [50, 0, 0]\n"));
    EXPECT_TRUE(has_one_error(load_level_file(file), 3, 1, "obstacle 1 needs the key 'model'"));
}

TEST_F(ModelPaths, EmptyPathIsRefused) {
    EXPECT_TRUE(has_one_error(load_with_model(""), 5, 9, "model path is empty"));
}

TEST(ModelPathRules, IsInsideComparesWholeComponents) {
    EXPECT_TRUE(is_inside("/a/b/c.obj", "/a/b"));
    EXPECT_TRUE(is_inside("/a/b/c.obj", "/a/b/"));
    EXPECT_FALSE(is_inside("/a/bc/d.obj", "/a/b"));
    EXPECT_FALSE(is_inside("/a", "/a/b"));
    EXPECT_FALSE(is_inside("/a/b", ""));
}

TEST(LoadFile, MissingAndOversizedFiles) {
    ScratchDir dir;
    const auto missing = load_level_file(dir.path() / "nope.toml");
    ASSERT_EQ(missing.errors.size(), 1u);
    EXPECT_EQ(format(missing.errors[0]),
              (dir.path() / "nope.toml").string() + ":1:1: error: file not found");
    const fs::path big = dir.write("big.toml", std::string(2u << 20, '#'));
    const auto too_big = load_level_file(big);
    ASSERT_EQ(too_big.errors.size(), 1u);
    EXPECT_NE(too_big.errors[0].message.find("over the limit of 1048576"), std::string::npos);
    const auto not_file = load_level_file(dir.path());
    ASSERT_EQ(not_file.errors.size(), 1u);
    EXPECT_NE(not_file.errors[0].message.find("not a regular file"), std::string::npos);
}

}  // namespace
}  // namespace bz::level
