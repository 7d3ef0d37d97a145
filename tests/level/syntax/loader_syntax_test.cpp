// Syntax errors: exact positions, and every one of them rather than only the first.
#include <gtest/gtest.h>

#include "level/level_test_util.h"
#include "level/loader.h"

namespace bz::level {
namespace {

using test::has_one_error;
using test::level_text;

using test::load_text;
TEST(LoaderSyntax, MissingValue) {
    const auto r = load_text(level_text("[field]\nsize =\n"));
    EXPECT_TRUE(has_one_error(r, 4, 7, "syntax error"));
}

TEST(LoaderSyntax, UnterminatedString) {
    //                           1234567890
    const auto r = load_text("version = 1\nname = \"abc\n");
    EXPECT_TRUE(has_one_error(r, 2, 12, "syntax error in string"));
}

TEST(LoaderSyntax, DuplicateKey) {
    const auto r = load_text(level_text("[field]\nsize = 100\nsize = 200\n"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].pos.line, 5);
    EXPECT_NE(r.errors[0].message.find("redefine"), std::string::npos) << r.errors[0].message;
}

TEST(LoaderSyntax, InvalidUtf8) {
    const auto r = load_text(level_text("author = \"\xff\"\n"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].pos.line, 3);
    EXPECT_NE(r.errors[0].message.find("utf-8"), std::string::npos) << r.errors[0].message;
}

TEST(LoaderSyntax, ReportsEverySyntaxErrorNotJustTheFirst) {
    const auto r =
        load_text(level_text("[field]\n"
                             "size = 40O\n"  // line 4: stray letter
                             "wrap = tru\n"  // line 5: bad boolean
                             "[player]\n"
                             "heading = = 3\n"  // line 7
                             "[render]\n"
                             "style = \"arcade\"\n"));
    ASSERT_EQ(r.errors.size(), 3u);
    EXPECT_EQ(r.errors[0].pos.line, 4);
    EXPECT_EQ(r.errors[0].pos.column, 10);
    EXPECT_EQ(r.errors[1].pos.line, 5);
    EXPECT_EQ(r.errors[2].pos.line, 7);
    EXPECT_EQ(r.errors[2].pos.column, 11);
    EXPECT_FALSE(r.level);
}

TEST(LoaderSyntax, ErrorInsideMultiLineArraySkipsTheWholeValue) {
    const auto r =
        load_text(level_text("[backdrop]\n"
                             "mountains = [\n"
                             "  [0, 1],\n"
                             "  [10, 2] x,\n"  // line 6: error inside the array
                             "  [20, 1],\n"
                             "]\n"
                             "moon = maybe\n"));  // line 9: a second, separate error
    ASSERT_EQ(r.errors.size(), 2u) << format(r.errors[0]);
    EXPECT_EQ(r.errors[0].pos.line, 6);
    EXPECT_EQ(r.errors[0].pos.column, 11);
    EXPECT_EQ(r.errors[1].pos.line, 9);
    EXPECT_EQ(r.errors[1].pos.column, 8);
}

TEST(LoaderSyntax, UnclosedArrayDoesNotCascade) {
    // The missing ']' swallows the rest of the file; one error, not one per following line.
    const auto r =
        load_text(level_text("[backdrop]\nmountains = [[0, 1], [10, 2]\nmoon = true\n"
                             "[render]\nstyle = \"arcade\"\npreset = \"high\"\n"));
    ASSERT_EQ(r.errors.size(), 1u) << format(r.errors[0]);
    // Reported on the line that lacks the ']', after its last character, not on the next line.
    EXPECT_EQ(r.errors[0].pos.line, 4);
    EXPECT_EQ(r.errors[0].pos.column, 29);
    EXPECT_NE(r.errors[0].message.find("missing ']'"), std::string::npos) << r.errors[0].message;
}

TEST(LoaderSyntax, MissingBracketBeforeACommentOrBlankLines) {
    const auto r =
        load_text(level_text("[enemies]\ntypes = [\"slow_tank\", \"missile\"   # two\n\n"
                             "aggression = 0.5\n"));
    ASSERT_EQ(r.errors.size(), 1u) << format(r.errors[0]);
    EXPECT_EQ(r.errors[0].pos.line, 4);
    EXPECT_EQ(r.errors[0].pos.column, 32);
    EXPECT_NE(r.errors[0].message.find("missing ']'"), std::string::npos) << r.errors[0].message;
    // A line that ends in ',' is a list going on: the error stays where toml++ found it.
    const auto list =
        load_text(level_text("[enemies]\ntypes = [\"slow_tank\",\naggression = 0.5\n"));
    ASSERT_EQ(list.errors.size(), 1u);
    EXPECT_EQ(list.errors[0].pos.line, 5);
}

TEST(LoaderSyntax, RecoveryKeepsTheTableContext) {
    // After the error the rest is read as part of [field] still: the repeated key is found...
    const auto dup = load_text(level_text("[field]\nsize = = 1\nwrap = true\nwrap = false\n"));
    ASSERT_EQ(dup.errors.size(), 2u);
    EXPECT_EQ(dup.errors[0].pos.line, 4);
    EXPECT_EQ(dup.errors[1].pos.line, 6);
    EXPECT_NE(dup.errors[1].message.find("redefine"), std::string::npos) << dup.errors[1].message;
    // ...and a key that belongs to [render] does not clash with a later [field] table.
    const auto ctx = load_text(level_text("[render]\nbad = = 1\nfield = 1\n[field]\nsize = 100\n"));
    ASSERT_EQ(ctx.errors.size(), 1u);
    EXPECT_EQ(ctx.errors[0].pos.line, 4);
}

TEST(LoaderSyntax, DeeplyDottedKeyIsRefusedBeforeParsing) {
    std::string key = "a";
    for (int i = 0; i < 100000; ++i) key += ".a";
    const auto r = load_text(level_text("  " + key + " = 1\n"));
    EXPECT_TRUE(has_one_error(r, 3, 3, "nested more than"));
}

TEST(LoaderSyntax, DeeplyNestedArrayIsAnErrorNotACrash) {
    const auto r = load_text(level_text("x = " + std::string(5000, '[') + "\n"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].pos.line, 3);
}

TEST(LoaderSyntax, MessagesStayOnOneLine) {
    const auto r = load_text(level_text("x = \"a\x01b\"\n"));
    ASSERT_FALSE(r.errors.empty());
    for (const auto& e : r.errors) EXPECT_EQ(format(e).find('\n'), std::string::npos) << format(e);
}

TEST(LoaderSyntax, FormatIsFileLineColumn) {
    const auto r = load_text(level_text("[field]\nsize =\n"));
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(format(r.errors[0]).rfind("levels/test.toml:4:7: error: syntax error", 0), 0u)
        << format(r.errors[0]);
}

}  // namespace
}  // namespace bz::level
