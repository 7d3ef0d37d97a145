// Inputs that toml++ 3.3 mishandles are reported as syntax errors before it sees them, and
// everything around them still works: Unicode in strings and comments, a byte order mark.
#include <gtest/gtest.h>

#include "level/level_test_util.h"
#include "level/loader.h"
#include "level/syntax/toml_scan.h"

namespace bz::level {
namespace {

using test::has_one_error;
using test::level_text;

using test::load_text;
TEST(TomlGuard, NonAsciiOutsideStringsIsASyntaxError) {
    // U+00DD after a number sent toml++ into __builtin_unreachable() (found by the fuzzer).
    EXPECT_TRUE(has_one_error(load_text(level_text("[field]\nsize = 1\xc3\x9d\n")), 4, 9,
                              "syntax error: non-ASCII character outside a string or comment"));
    EXPECT_TRUE(has_one_error(load_text(level_text("\xc3\x9d = 1\n")), 3, 1,
                              "non-ASCII character outside"));
    // A quote glued to a bare value does not start a string: toml++ is still reading the value.
    EXPECT_TRUE(has_one_error(load_text(level_text("x = 1:*'''\xef\xbb\xa0'''\n")), 3, 11,
                              "non-ASCII character outside"));
}

TEST(TomlGuard, AQuotedKeySegmentAfterADotIsAString) {
    // v." =" is a dotted key whose second part is quoted: the value after it lies outside any
    // string. The scanner took that quote for code and the next one for a string's start, so
    // toml++ got the non-ASCII value and hit __builtin_unreachable() (found by the fuzzer).
    EXPECT_TRUE(has_one_error(load_text(level_text("v.\" =\"=\xca\x9c\n")), 3, 8,
                              "non-ASCII character outside"));
    EXPECT_TRUE(has_one_error(load_text(level_text("x = {a.\" =\"=\xca\x9c}\n")), 3, 13,
                              "non-ASCII character outside"));
    EXPECT_TRUE(has_one_error(load_text(level_text("[a.\"=\"]\xca\x9c\n")), 3, 8,
                              "non-ASCII character outside"));
    // In a value a quote after a dot is still part of a bare value, as toml++ reads it.
    EXPECT_TRUE(has_one_error(load_text(level_text("x = 1.\"\xca\x9c\"\n")), 3, 8,
                              "non-ASCII character outside"));
    EXPECT_TRUE(has_one_error(load_text(level_text("x = [1, 2.\"\xca\x9c\"]\n")), 3, 12,
                              "non-ASCII character outside"));
    // A quoted key segment with Unicode in it is fine.
    const auto r = load_text(level_text("[backdrop]\n\"\xc3\xa9\".x = 1\n"));
    EXPECT_TRUE(r.errors.empty() || r.errors.at(0).message.find("non-ASCII") == std::string::npos);
}

TEST(TomlGuard, NonAsciiAfterABackslashInAMultiLineString) {
    EXPECT_TRUE(has_one_error(load_text("version = 1\nname = \"\"\"a\\\xc3\x9d\"\"\"\n"), 2, 13,
                              "non-ASCII character after a backslash"));
    EXPECT_TRUE(has_one_error(load_text("version = 1\nname = \"\"\"a\\ \xc3\x9d\"\"\"\n"), 2, 14,
                              "right after a line-ending backslash"));
    EXPECT_TRUE(has_one_error(load_text("version = 1\nname = \"\"\"a\\\n  \xc3\x9d\"\"\"\n"), 3, 3,
                              "right after a line-ending backslash"));
}

TEST(TomlGuard, UnicodeInStringsAndCommentsIsFine) {
    const auto r = load_text(
        "version = 1 # \xc3\xa9t\xc3\xa9\nname = \"Zo\xc3\xab's field\"\n"
        "author = '''\xe2\x98\x85'''\ndescription = \"\"\"\xc3\x9d and \xc3\x9d\"\"\"\n");
    ASSERT_TRUE(r.ok()) << format(r.errors.at(0));
    EXPECT_EQ(r.level->name, "Zo\xc3\xab's field");
    EXPECT_EQ(r.level->author, "\xe2\x98\x85");
}

TEST(TomlGuard, ByteOrderMarkIsAccepted) {
    const auto r = load_text("\xef\xbb\xbfversion = 1\nname = \"x\"\n");
    EXPECT_TRUE(r.ok());
}

TEST(TomlGuard, ColumnsCountCharactersNotBytes) {
    // Three two-byte characters before the error: column 16 by characters (19 by bytes).
    const auto r = load_text(level_text("author = \"\xc3\xa9\xc3\xa9\xc3\xa9\" x\n"));
    EXPECT_TRUE(has_one_error(r, 3, 16, "syntax error"));
}

TEST(TomlGuard, RecoveryContinuesAfterAGuardedCharacter) {
    const auto r = load_text(level_text("[field]\nsize = 1\xc3\x9d\nwrap = tru\n"));
    ASSERT_EQ(r.errors.size(), 2u);
    EXPECT_EQ(r.errors[0].pos.line, 4);
    EXPECT_EQ(r.errors[1].pos.line, 5);
}

TEST(TomlScan, StatesAcrossStringsCommentsAndBrackets) {
    ScanState s;
    const std::string_view text = "a = [1, \"]\", '[' # ]\n";
    scan(text, 0, text.size(), s);
    EXPECT_EQ(s.brackets, "[");
    EXPECT_TRUE(s.inside_value());
    ScanState m;
    const std::string_view ml = "x = \"\"\"open\n";
    scan(ml, 0, ml.size(), m);
    EXPECT_TRUE(m.inside_value());
    EXPECT_EQ(line_start("a\nb\nc", 3), 4u);
    EXPECT_EQ(line_start("a\nb", 5), std::string_view::npos);
}

TEST(TomlScan, DeepKeysAreFound) {
    EXPECT_FALSE(find_deep_key("a.b.c = 1.5\nx = [1.5, 2.5]\n", 3));
    const auto deep = find_deep_key("ok = 1\n[a.b.c.d.e]\n", 3);
    ASSERT_TRUE(deep);
    EXPECT_EQ(deep->offset, 8u);
    EXPECT_FALSE(find_deep_key("s = \"a.b.c.d.e.f\"\n", 3));  // dots in strings do not nest
}

}  // namespace
}  // namespace bz::level
