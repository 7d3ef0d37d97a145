// [render] material_lines: a boolean, unset by default (the renderer's default, off, holds),
// and a value of another type reported at its position.
#include <gtest/gtest.h>

#include "level/loader.h"
#include "level_test_util.h"

namespace bz::level {
namespace {

TEST(MaterialLinesKey, UnsetByDefaultAndTakesABoolean) {
    const auto plain = test::load_text(test::level_text(""), {});
    ASSERT_TRUE(plain.ok());
    EXPECT_FALSE(plain.level->render.material_lines.has_value());
    for (const bool on : {true, false}) {
        const auto r = test::load_text(test::level_text(std::string("[render]\nmaterial_lines = ") +
                                                        (on ? "true" : "false") + "\n"),
                                       {});
        ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
        EXPECT_EQ(r.level->render.material_lines, on);
    }
}

TEST(MaterialLinesKey, AnotherTypeIsReportedAtItsPosition) {
    const auto r = test::load_text(test::level_text("[render]\nmaterial_lines = \"yes\"\n"), {});
    EXPECT_TRUE(test::has_one_error(r, 4, 18, "material_lines"));
}

}  // namespace
}  // namespace bz::level
