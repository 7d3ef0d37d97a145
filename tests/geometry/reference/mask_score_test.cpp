#include "geometry/reference/mask_score.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace bz::geo {
namespace {

std::vector<std::uint8_t> blank() {
    return std::vector<std::uint8_t>(20 * 10, 0);
}
void set(std::vector<std::uint8_t>& m, int x, int y) {
    m[static_cast<std::size_t>(y * 20 + x)] = 255;
}

TEST(MaskScore, IdenticalMasksScoreOne) {
    auto a = blank();
    for (int x = 2; x < 15; ++x) set(a, x, 4);
    const MaskScore s = score_masks(a, a, 20, 10, 0);
    EXPECT_EQ(s.precision, 1.0);
    EXPECT_EQ(s.recall, 1.0);
    EXPECT_EQ(s.f1, 1.0);
    EXPECT_EQ(s.test_lit, 13u);
}

TEST(MaskScore, OnePixelShiftIsForgivenOnlyWithTolerance) {
    auto a = blank(), b = blank();
    for (int x = 2; x < 12; ++x) {
        set(a, x, 4);
        set(b, x, 5);
    }
    EXPECT_EQ(score_masks(a, b, 20, 10, 1).f1, 1.0);
    EXPECT_EQ(score_masks(a, b, 20, 10, 0).f1, 0.0);
    // Two pixels off is beyond a 1-pixel tolerance.
    auto c = blank();
    for (int x = 2; x < 12; ++x) set(c, x, 6);
    EXPECT_EQ(score_masks(a, c, 20, 10, 1).f1, 0.0);
    EXPECT_EQ(score_masks(a, c, 20, 10, 2).f1, 1.0);
}

TEST(MaskScore, PrecisionAndRecallCountTheRightSide) {
    auto ref = blank(), test = blank();
    for (int x = 0; x < 10; ++x) set(ref, x, 2);
    for (int x = 0; x < 5; ++x) set(test, x, 2);  // half the reference
    for (int x = 0; x < 5; ++x) set(test, x, 8);  // plus as many wrong pixels
    const MaskScore s = score_masks(test, ref, 20, 10, 1);
    EXPECT_DOUBLE_EQ(s.precision, 0.5);
    EXPECT_DOUBLE_EQ(s.recall, 0.6);  // x = 5 is within 1 px of the test's x = 4
    EXPECT_DOUBLE_EQ(s.f1, 2.0 * 0.5 * 0.6 / 1.1);
}

TEST(MaskScore, EmptyMasks) {
    auto ref = blank();
    set(ref, 3, 3);
    EXPECT_EQ(score_masks(blank(), blank(), 20, 10, 1).f1, 1.0);
    const MaskScore s = score_masks(blank(), ref, 20, 10, 1);
    EXPECT_EQ(s.recall, 0.0);
    EXPECT_EQ(s.f1, 0.0);
    EXPECT_THROW(score_masks(blank(), std::vector<std::uint8_t>(5), 20, 10, 1),
                 std::invalid_argument);
    EXPECT_THROW(score_masks(blank(), blank(), 20, 10, -1), std::invalid_argument);
}

}  // namespace
}  // namespace bz::geo
