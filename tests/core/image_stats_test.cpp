#include "core/image_stats.h"

#include <gtest/gtest.h>

namespace {

bz::Image rgba(int w, int h) {
    return {w, h, 4, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h * 4), 0)};
}

void set(bz::Image& img, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b,
         std::uint8_t a = 255) {
    auto* p = &img.pixels[static_cast<std::size_t>((y * img.width + x) * 4)];
    p[0] = r;
    p[1] = g;
    p[2] = b;
    p[3] = a;
}

}  // namespace

TEST(LitShare, CountsPixelsWhoseBrightestChannelIsAboveTheLevel) {
    bz::Image img = rgba(4, 2);  // 8 pixels
    set(img, 0, 0, 0, 2, 0);     // green 2/255: above 1/255
    set(img, 1, 0, 1, 1, 1);     // 1/255 in every channel: not above
    set(img, 2, 0, 0, 0, 200);   // blue only
    set(img, 3, 1, 255, 0, 0);   // red only
    EXPECT_DOUBLE_EQ(bz::lit_share(img), 3.0 / 8.0);
    EXPECT_DOUBLE_EQ(bz::lit_share(img, 0), 4.0 / 8.0);
    EXPECT_DOUBLE_EQ(bz::lit_share(img, 199), 2.0 / 8.0);
}

TEST(LitShare, IgnoresAlphaAndReadsGrayImages) {
    bz::Image img = rgba(2, 1);
    set(img, 0, 0, 0, 0, 0, 255);  // black but opaque: not lit
    EXPECT_DOUBLE_EQ(bz::lit_share(img), 0.0);
    const bz::Image gray{3, 1, 1, {0, 5, 1}};
    EXPECT_DOUBLE_EQ(bz::lit_share(gray), 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(bz::lit_share(bz::Image{}), 0.0);
}
