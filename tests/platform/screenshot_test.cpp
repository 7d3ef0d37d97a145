#include "platform/screenshot.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "core/image_io.h"
#include "support/scratch_dir.h"

namespace bz::platform {
namespace {

namespace fs = std::filesystem;

class Screenshots : public ::testing::Test {
  protected:
    bz::test::ScratchDir scratch_{"bz_shots"};
    const fs::path dir_ = scratch_.path();
};

std::vector<std::uint8_t> gradient(int w, int h) {
    std::vector<std::uint8_t> p;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            p.insert(p.end(), {static_cast<std::uint8_t>(x * 10), static_cast<std::uint8_t>(y * 10),
                               7, 255});
        }
    }
    return p;
}

TEST_F(Screenshots, NumbersCountUpAndPixelsSurvive) {
    const fs::path first = save_screenshot(dir_ / "screenshots", 4, 3, gradient(4, 3));
    EXPECT_EQ(first.filename(), "screenshot-0001.png");
    const fs::path second = save_screenshot(dir_ / "screenshots", 4, 3, gradient(4, 3));
    EXPECT_EQ(second.filename(), "screenshot-0002.png");
    const Image back = read_png(second, 4);
    ASSERT_EQ(back.width, 4);
    ASSERT_EQ(back.height, 3);
    EXPECT_EQ(back.at(3, 2, 0), 30);
    EXPECT_EQ(back.at(3, 2, 1), 20);  // row 0 stays at the top
    EXPECT_EQ(back.at(0, 0, 2), 7);
}

TEST_F(Screenshots, NextNumberIsPastTheHighest) {
    fs::create_directories(dir_);
    for (const char* name : {"screenshot-0003.png", "screenshot-0041.png", "screenshot-x.png",
                             "notes.txt", "screenshot-0099.jpg"}) {
        std::ofstream(dir_ / name) << "x";
    }
    EXPECT_EQ(next_screenshot_path(dir_).filename(), "screenshot-0042.png");
    EXPECT_EQ(next_screenshot_path(dir_ / "missing").filename(), "screenshot-0001.png");
}

TEST_F(Screenshots, MismatchedBufferIsAnError) {
    EXPECT_THROW(save_screenshot(dir_, 4, 4, gradient(4, 3)), UserError);
    EXPECT_THROW(save_screenshot(dir_, 0, 0, {}), UserError);
}

}  // namespace
}  // namespace bz::platform
