#include "app/play/menu/level_list.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "level/loader.h"
#include "support/scratch_dir.h"

namespace bz::app::menu {
namespace {

void write(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

TEST(LevelList, ShippedLevelsShowTheirNamesTutorialFirstAndNoBenchmark) {
    const auto shipped = level::default_level_path().parent_path();
    const std::vector<LevelChoice> levels = find_levels(shipped, shipped / "no-such-folder");
    ASSERT_GE(levels.size(), 3u);
    EXPECT_EQ(levels[0].name, "FIRST STEPS");
    EXPECT_EQ(levels[0].file.filename(), "tutorial.toml");
    EXPECT_EQ(levels[1].name, "CLASSIC");
    EXPECT_FALSE(levels[0].description.empty());
    for (const LevelChoice& l : levels) {
        EXPECT_NE(l.file.filename(), "stress.toml") << "a benchmark scene, not a level to play";
        EXPECT_TRUE(l.loads) << l.file;
        EXPECT_FALSE(l.description.empty()) << l.file << " has no one-line description";
    }
    const auto volcano = std::find_if(levels.begin(), levels.end(), [](const LevelChoice& l) {
        return l.file.filename() == "volcano_night.toml";
    });
    ASSERT_NE(volcano, levels.end());
    EXPECT_EQ(volcano->name, "NIGHT VOLCANO");  // the level's name, not the file's
    // Every shipped description is shown whole (the tutorial's is 86 characters): none is cut.
    for (const LevelChoice& l : levels) {
        EXPECT_EQ(l.description.find("..."), std::string::npos) << l.description;
    }
}

TEST(LevelList, UserLevelsFollowSortedByOrderThenNameAndBrokenOnesAreFlagged) {
    const bz::test::ScratchDir dir("bz_level_list");
    const auto shipped = dir.path() / "shipped";
    const auto user = dir.path() / "user";
    std::filesystem::create_directories(shipped);
    std::filesystem::create_directories(user);
    write(shipped / "b.toml", "version = 1\nname = \"Bravo\"\ndescription = \"Second.\"\n");
    write(shipped / "a.toml", "version = 1\nname = \"Zulu\"\nmenu_order = 5\n");
    write(shipped / "hidden.toml", "version = 1\nname = \"Bench\"\nlisted = false\n");
    write(user / "mine.toml", "version = 1\nname = \"Mine\"\n");
    write(user / "broken_one.toml", "version = 1\nname = \n");
    write(user / "notes.txt", "not a level");
    const std::vector<LevelChoice> l = find_levels(shipped, user);
    ASSERT_EQ(l.size(), 4u);
    EXPECT_EQ(l[0].name, "ZULU");  // menu_order 5 before the default 100
    EXPECT_EQ(l[1].name, "BRAVO");
    EXPECT_EQ(l[1].description, "SECOND.");
    EXPECT_FALSE(l[1].user);
    EXPECT_EQ(l[2].name, "BROKEN ONE");
    EXPECT_FALSE(l[2].loads);
    EXPECT_TRUE(l[2].user);
    EXPECT_EQ(l[3].name, "MINE");
    // The hidden one still loads by path.
    EXPECT_TRUE(level::load_level_file(shipped / "hidden.toml").level.has_value());
}

}  // namespace
}  // namespace bz::app::menu
