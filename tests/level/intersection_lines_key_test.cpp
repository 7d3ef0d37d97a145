// [render] intersection_lines: a boolean, unset by default (the renderer's default, off,
// holds), and a value of another type reported at its position.
#include <gtest/gtest.h>

#include "level/loader.h"
#include "level_test_util.h"

namespace bz::level {
namespace {

TEST(IntersectionLinesKey, UnsetByDefaultAndTakesABoolean) {
    const auto plain = test::load_text(test::level_text(""), {});
    ASSERT_TRUE(plain.ok());
    EXPECT_FALSE(plain.level->render.intersection_lines.has_value());
    for (const bool on : {true, false}) {
        const auto r =
            test::load_text(test::level_text(std::string("[render]\nintersection_lines = ") +
                                             (on ? "true" : "false") + "\n"),
                            {});
        ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
        EXPECT_EQ(r.level->render.intersection_lines, on);
    }
}

TEST(IntersectionLinesKey, AnotherTypeIsReportedAtItsPosition) {
    const auto r = test::load_text(test::level_text("[render]\nintersection_lines = 1\n"), {});
    EXPECT_TRUE(test::has_one_error(r, 4, 22, "intersection_lines"));
}

}  // namespace
}  // namespace bz::level
