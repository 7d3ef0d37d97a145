#include "scene/vector_font.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "support/scratch_dir.h"

namespace bz::scene {
namespace {

namespace fs = std::filesystem;

struct Box {
    glm::vec2 lo{1e9f};
    glm::vec2 hi{-1e9f};
};

Box bounds(const std::vector<HudLine>& lines) {
    Box b;
    for (const auto& l : lines) {
        for (const glm::vec2 p : {l.a, l.b}) {
            b.lo = glm::min(b.lo, p);
            b.hi = glm::max(b.hi, p);
        }
    }
    return b;
}

// Font files made by a test live in a folder of their own, removed afterwards.
class FontFiles : public ::testing::Test {
  protected:
    fs::path write_temp(const std::string& name, const std::string& content) {
        return dir_.write(name, content);
    }

  private:
    bz::test::ScratchDir dir_{"bz_font_test"};
};

std::string error_of(const fs::path& p) {
    try {
        VectorFont f(p);
    } catch (const UserError& e) {
        return e.what();
    }
    return "";
}

TEST(VectorFont, DefaultFontHasPrintableAscii) {
    const VectorFont font = VectorFont::load_default();
    EXPECT_EQ(font.glyph_count(), 96u);  // ' ' .. DEL
}

TEST(VectorFont, CapitalsSitBetweenBaselineAndCapHeight) {
    const VectorFont font = VectorFont::load_default();
    std::vector<HudLine> lines;
    const glm::vec2 origin{-0.5f, 0.25f};
    const float height = 0.1f;
    font.draw(lines, "HELLO", origin, height, {1.0f, 0.0f, 0.0f});
    ASSERT_FALSE(lines.empty());
    const Box b = bounds(lines);
    const float eps = 1e-4f;
    EXPECT_NEAR(b.lo.y, origin.y, eps);           // H, E, L sit on the baseline
    EXPECT_NEAR(b.hi.y, origin.y + height, eps);  // and reach exactly the cap height
    EXPECT_GE(b.lo.x, origin.x - eps);
    EXPECT_LE(b.hi.x, origin.x + font.width("HELLO", height) + eps);
    for (const auto& l : lines) {
        EXPECT_EQ(l.color, glm::vec3(1.0f, 0.0f, 0.0f));
        EXPECT_EQ(l.intensity, 1.0f);
    }
}

TEST(VectorFont, DescendersGoBelowTheBaseline) {
    const VectorFont font = VectorFont::load_default();
    std::vector<HudLine> lines;
    font.draw(lines, "gjpqy", {0.0f, 0.0f}, 1.0f, {1, 1, 1});
    EXPECT_LT(bounds(lines).lo.y, -0.2f);
}

TEST(VectorFont, WidthScalesLinearlyAndAddsUp) {
    const VectorFont font = VectorFont::load_default();
    const float w1 = font.width("SCORE 1200", 1.0f);
    EXPECT_GT(w1, 3.0f);  // ten glyphs, each roughly 0.5..1 cap heights wide
    EXPECT_NEAR(font.width("SCORE 1200", 0.25f), 0.25f * w1, 1e-5f);
    EXPECT_NEAR(font.width("SCORE", 1.0f) + font.width(" 1200", 1.0f), w1, 1e-5f);
    EXPECT_EQ(font.width("", 1.0f), 0.0f);
}

TEST(VectorFont, AlignmentShiftsByWidth) {
    const VectorFont font = VectorFont::load_default();
    const float w = font.width("RADAR", 0.2f);
    std::vector<HudLine> left, center, right;
    font.draw(left, "RADAR", {0, 0}, 0.2f, {1, 1, 1}, TextAlign::left);
    font.draw(center, "RADAR", {0, 0}, 0.2f, {1, 1, 1}, TextAlign::center);
    font.draw(right, "RADAR", {0, 0}, 0.2f, {1, 1, 1}, TextAlign::right);
    ASSERT_EQ(left.size(), center.size());
    ASSERT_EQ(left.size(), right.size());
    for (std::size_t i = 0; i < left.size(); ++i) {
        EXPECT_NEAR(center[i].a.x, left[i].a.x - 0.5f * w, 1e-5f);
        EXPECT_NEAR(right[i].b.x, left[i].b.x - w, 1e-5f);
    }
}

TEST(VectorFont, UnknownCharactersDrawAsSpaces) {
    const VectorFont font = VectorFont::load_default();
    // A tab, a control byte, DEL-range bytes and a two-byte UTF-8 character (é).
    const std::string odd = std::string("A\tB\x01") + "\xc3\xa9" + "\xff";
    std::vector<HudLine> odd_lines, plain_lines;
    font.draw(odd_lines, odd, {0, 0}, 1.0f, {1, 1, 1});
    font.draw(plain_lines, "A B", {0, 0}, 1.0f, {1, 1, 1});
    EXPECT_EQ(odd_lines.size(), plain_lines.size());  // only A and B draw anything
    const float space = font.width(" ", 1.0f);
    EXPECT_GT(space, 0.0f);
    // A, B and four unknown characters (tab, \x01, é as one, \xff) of one space each.
    EXPECT_NEAR(font.width(odd, 1.0f), font.width("AB", 1.0f) + 4 * space, 1e-5f);
}

TEST_F(FontFiles, ParsesPenUpAndMargins) {
    // Glyph ' ' (advance 16) and '!' : a vertical bar, pen up, a dot drawn as a short stroke.
    const fs::path p = write_temp("tiny.jhf",
                                  "12345  1JZ\n"
                                  "12345  6MWRFRT RRYRZ\n");
    const VectorFont font(p);
    EXPECT_EQ(font.glyph_count(), 2u);
    std::vector<HudLine> lines;
    font.draw(lines, "!", {0, 0}, 21.0f, {1, 1, 1});  // 21 units: the Hershey default cap
    ASSERT_EQ(lines.size(), 2u);
    // x: R - M = 5 units right of the left margin; y: baseline 9 - file y.
    EXPECT_FLOAT_EQ(lines[0].a.x, 5.0f);
    EXPECT_FLOAT_EQ(lines[0].a.y, 9.0f - (-12.0f));
    EXPECT_FLOAT_EQ(lines[0].b.y, 9.0f - 2.0f);
    EXPECT_FLOAT_EQ(font.width("!", 21.0f), 10.0f);
    EXPECT_FLOAT_EQ(font.width(" ", 21.0f), 16.0f);
}

TEST_F(FontFiles, ContinuationLinesAreJoined) {
    const fs::path p = write_temp("wrapped.jhf",
                                  "12345  1JZ\n"
                                  "12345  6MWRF\n"
                                  "RT RRYRZ\n");
    const VectorFont font(p);
    EXPECT_EQ(font.glyph_count(), 2u);
}

TEST_F(FontFiles, MalformedFilesNameFileAndLine) {
    const fs::path bad_count = write_temp("bad_count.jhf", "12345  1JZ\n12345 x6MWRFRT\n");
    const std::string e1 = error_of(bad_count);
    EXPECT_NE(e1.find(bad_count.string() + ":2:"), std::string::npos) << e1;
    EXPECT_NE(e1.find("error:"), std::string::npos) << e1;

    const fs::path truncated = write_temp("truncated.jhf", "12345  1JZ\n12345  9MWRFRT\n");
    const std::string e2 = error_of(truncated);
    EXPECT_NE(e2.find(truncated.string() + ":2:"), std::string::npos) << e2;
    EXPECT_NE(e2.find("9 vertices"), std::string::npos) << e2;

    const fs::path short_header = write_temp("short.jhf", "12345  1JZ\n\n123\n");
    EXPECT_NE(error_of(short_header).find(short_header.string() + ":3:"), std::string::npos);

    const fs::path bad_char = write_temp("bad_char.jhf", "12345  2JZR\x7f\n");
    EXPECT_NE(error_of(bad_char).find(bad_char.string() + ":1:"), std::string::npos);

    const fs::path too_long = write_temp("long.jhf", "12345  1JZRR\n");
    EXPECT_NE(error_of(too_long).find(":1:"), std::string::npos);

    const fs::path empty = write_temp("empty.jhf", "\n\n");
    EXPECT_NE(error_of(empty).find("no glyphs"), std::string::npos);

    EXPECT_NE(error_of("/nonexistent/font.jhf").find("/nonexistent/font.jhf"), std::string::npos);
}

}  // namespace
}  // namespace bz::scene
