// The levels in levels/ load cleanly with the real data/ folder, and each is what
// levels/README.md says it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/io/file_io.h"
#include "level/loader.h"
#include "support/tree_paths.h"

namespace bz::level {
namespace {

namespace fs = std::filesystem;

fs::path levels() {
    return bz::test::source_dir() / "levels";
}

Level load_shipped(const std::string& name) {
    const LoadResult r = load_level_file(levels() / name);
    for (const auto& e : r.errors) ADD_FAILURE() << format(e);
    return r.level.value_or(Level{});
}

TEST(ShippedLevels, AllLoadWithoutErrors) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(levels())) {
        if (entry.path().extension() != ".toml") continue;
        const LoadResult r = load_level_file(entry.path());
        EXPECT_TRUE(r.ok()) << entry.path();
        for (const auto& e : r.errors) ADD_FAILURE() << format(e);
        ++count;
    }
    EXPECT_GE(count, 6);
}

TEST(ShippedLevels, DefaultIsTheClassicField) {
    EXPECT_EQ(default_level_path().filename(), "classic.toml");
    const Level l = load_shipped("classic.toml");
    EXPECT_EQ(l.obstacles.size(), 21u);
    EXPECT_TRUE(l.wrap);
    EXPECT_TRUE(l.enemies.slow_tank && l.enemies.super_tank && l.enemies.missile &&
                l.enemies.saucer);
}

// The ROM's battlefield: its 21 obstacles are the arcade's own four kinds, at scale 1, as many
// of each as the ROM table has (6 wide pyramids, 5 narrow, 5 tall boxes, 5 short).
TEST(ShippedLevels, Battlefield1980UsesTheArcadesFourShapes) {
    const Level l = load_shipped("battlefield_1980.toml");
    ASSERT_EQ(l.obstacles.size(), 21u);
    EXPECT_EQ(l.field_size, 256.0);
    EXPECT_TRUE(l.wrap);
    const auto count = [&](const char* kind) {
        return std::count_if(l.obstacles.begin(), l.obstacles.end(),
                             [&](const ObjectDesc& o) { return o.kind == kind; });
    };
    EXPECT_EQ(count("arcade_wide_pyramid"), 6);
    EXPECT_EQ(count("arcade_narrow_pyramid"), 5);
    EXPECT_EQ(count("arcade_tall_box"), 5);
    EXPECT_EQ(count("arcade_short_box"), 5);
    for (const ObjectDesc& o : l.obstacles) EXPECT_EQ(o.scale, 1.0) << o.kind;
    // The first row of the table: a wide pyramid at (32, 32), heading 0.
    EXPECT_EQ(l.obstacles.front().kind, "arcade_wide_pyramid");
    EXPECT_EQ(l.obstacles.front().position, glm::dvec3(32, 0, 32));
}

TEST(ShippedLevels, StressLevelHasHundredsOfObjectsAndImportedModels) {
    const Level l = load_shipped("stress.toml");
    EXPECT_GE(l.obstacles.size(), 300u);
    const auto models = std::count_if(l.obstacles.begin(), l.obstacles.end(),
                                      [](const ObjectDesc& o) { return o.kind == "model"; });
    EXPECT_GE(models, 50);
    for (const auto& o : l.obstacles) {
        if (o.kind == "model") {
            EXPECT_TRUE(fs::is_regular_file(o.model)) << o.model;
        }
    }
    EXPECT_GE(l.camera_path.size(), 2u);
}

TEST(ShippedLevels, EachHasItsOwnCharacter) {
    EXPECT_FALSE(load_shipped("maze.toml").wrap);
    EXPECT_GE(load_shipped("maze.toml").obstacles.size(), 100u);
    const Level tutorial = load_shipped("tutorial.toml");
    EXPECT_FALSE(tutorial.enemies.super_tank || tutorial.enemies.missile ||
                 tutorial.enemies.saucer);
    const Level night = load_shipped("volcano_night.toml");
    EXPECT_TRUE(night.backdrop.volcano);
    EXPECT_GE(load_shipped("plains.toml").field_size, 1000.0);
    EXPECT_GE(load_shipped("plains.toml").obstacles.size(), 100u);
}

}  // namespace
}  // namespace bz::level

namespace bz::level {
namespace {

// The complete example in levels/README.md must stay a valid level.
TEST(ShippedLevels, ReadmeExampleIsValid) {
    const std::string readme = read_file(bz::test::source_dir() / "levels" / "README.md");
    const auto heading = readme.find("## Example");
    ASSERT_NE(heading, std::string::npos);
    const auto begin = readme.find("```toml\n", heading);
    ASSERT_NE(begin, std::string::npos);
    const auto end = readme.find("```", begin + 8);
    ASSERT_NE(end, std::string::npos);
    const std::string example = readme.substr(begin + 8, end - begin - 8);
    const LoadResult r =
        load_level_string(example, bz::test::source_dir() / "levels" / "readme-example.toml");
    for (const auto& e : r.errors) ADD_FAILURE() << format(e);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.level->name, "Two Towers");
    EXPECT_EQ(r.level->obstacles.size(), 4u);
}

}  // namespace
}  // namespace bz::level
