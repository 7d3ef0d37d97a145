// Screenshot names when the folder already holds numbers at or past the end of the range:
// the counter must not overflow into one name that every later shot overwrites.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "platform/screenshot.h"
#include "support/scratch_dir.h"

namespace bz::platform {
namespace {

namespace fs = std::filesystem;

class ScreenshotNumbers : public ::testing::Test {
  protected:
    void touch(const std::string& name) { std::ofstream(dir_ / name) << "x"; }
    std::vector<std::uint8_t> pixels() { return std::vector<std::uint8_t>(2 * 2 * 4, 9); }
    bz::test::ScratchDir scratch_{"bz_shot_numbers"};
    const fs::path dir_ = scratch_.path();
};

TEST_F(ScreenshotNumbers, HugeExistingNumbersNeverMakeShotsShareAName) {
    touch("screenshot-9223372036854775807.png");      // LONG_MAX
    touch("screenshot-99999999999999999999999.png");  // past any integer type
    touch("screenshot-99999999.png");                 // the last number of the range
    std::set<fs::path> names;
    for (int i = 0; i < 5; ++i) {
        const fs::path p = save_screenshot(dir_, 2, 2, pixels());
        EXPECT_TRUE(names.insert(p).second) << "reused " << p;
        EXPECT_EQ(fs::file_size(p) > 8, true);
    }
    // The range is full at the top, so the lowest free numbers are taken.
    EXPECT_TRUE(names.count(dir_ / "screenshot-0001.png"));
    EXPECT_TRUE(names.count(dir_ / "screenshot-0005.png"));
}

TEST_F(ScreenshotNumbers, ExistingFilesAreNeverOverwritten) {
    touch("screenshot-0001.png");
    touch("screenshot-99999999.png");
    touch("screenshot-0002.png");
    const fs::path p = save_screenshot(dir_, 2, 2, pixels());
    EXPECT_EQ(p.filename(), "screenshot-0003.png");
    std::ifstream first(dir_ / "screenshot-0001.png");
    std::string content;
    first >> content;
    EXPECT_EQ(content, "x");
}

TEST_F(ScreenshotNumbers, NormalFolderCountsOnFromTheHighest) {
    touch("screenshot-0041.png");
    touch("notes.txt");
    EXPECT_EQ(next_screenshot_path(dir_).filename(), "screenshot-0042.png");
}

}  // namespace
}  // namespace bz::platform
