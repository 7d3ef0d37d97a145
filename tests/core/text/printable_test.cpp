// Untrusted text in messages: every control character, terminal escape and stray byte is
// shown as an escape, valid UTF-8 stays readable, and a huge value is cut to a bounded size.
#include "core/text/printable.h"

#include <gtest/gtest.h>

#include <string>

using bz::printable;

TEST(PrintableText, PlainTextIsUnchanged) {
    EXPECT_EQ(printable("levels/mine.toml"), "levels/mine.toml");
    EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x86\x92 ok"), "caf\xc3\xa9 \xe2\x86\x92 ok");
}

TEST(PrintableText, ControlCharactersBecomeEscapes) {
    EXPECT_EQ(printable(std::string("a\nb\tc\rd\0e", 9)), "a\\nb\\tc\\rd\\0e");
    EXPECT_EQ(printable("\x1b[2J\x1b]0;title\x07"), "\\e[2J\\e]0;title\\x07");
    EXPECT_EQ(printable("\x7f"), "\\x7f");
}

TEST(PrintableText, InvalidUtf8AndC1ControlsBecomeEscapes) {
    EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(printable("\xc2\x9b"
                        "31m"),
              "\\u{009b}31m");                                // 8-bit CSI, U+009B
    EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");           // overlong '/'
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
    EXPECT_EQ(printable("\xe2\x86"), "\\xe2\\x86");           // cut short
}

TEST(PrintableText, HugeTextIsCutWithACount) {
    const std::string huge(200u << 20, 'x');
    const std::string shown = printable(huge);
    EXPECT_LT(shown.size(), 300u);
    EXPECT_EQ(shown.substr(0, 200), std::string(200, 'x'));
    EXPECT_NE(shown.find("(209715000 more bytes)"), std::string::npos) << shown;
    EXPECT_EQ(printable("abcdef", 3), "abc... (3 more bytes)");
}

TEST(PrintableText, NoOutputByteIsAControlCharacter) {
    std::string all;
    for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
    const std::string shown = printable(all, all.size());
    for (const char c : shown) {
        const auto u = static_cast<unsigned char>(c);
        EXPECT_TRUE(u >= 0x20 && u != 0x7f) << static_cast<int>(u);
    }
}

TEST(PrintableText, BidiOverridesAndInvisibleCharactersBecomeEscapes) {
    EXPECT_EQ(printable("abc\xe2\x80\xaegnp.exe"),
              "abc\\u{202e}gnp.exe");  // RIGHT-TO-LEFT OVERRIDE
    EXPECT_EQ(printable("\xe2\x81\xa6x\xe2\x81\xa9"), "\\u{2066}x\\u{2069}");  // isolates
    EXPECT_EQ(printable("a\xe2\x80\x8b"
                        "b"),
              "a\\u{200b}b");                             // zero-width space
    EXPECT_EQ(printable("\xe2\x80\xa8"), "\\u{2028}");    // line separator
    EXPECT_EQ(printable("\xef\xbb\xbfx"), "\\u{feff}x");  // BOM
    EXPECT_EQ(printable("\xc2\x9b"), "\\u{009b}");        // C1 CSI
}

TEST(PrintableText, ACutNeverSplitsACharacter) {
    // 'é' is two bytes: a cut at 3 bytes of "aéé" keeps "aé", never half of the second.
    EXPECT_EQ(printable("a\xc3\xa9\xc3\xa9", 4), "a\xc3\xa9... (2 more bytes)");
    const std::string huge(100000, 'x');
    EXPECT_LT(printable(huge).size(), 260u);
}

TEST(PrintableText, MessagesKeepTheirLinesButNotTheirEscapes) {
    EXPECT_EQ(bz::printable_message("a\nb\tc\x1b[2Jd\xe2\x80\xae"), "a\nb\tc\\e[2Jd\\u{202e}");
    EXPECT_LT(bz::printable_message(std::string(1 << 20, 'x')).size(), (64u << 10) + 40);
}

TEST(PrintableText, MenuLabelsAreCutToAWidth) {
    EXPECT_EQ(bz::menu_label("short", 10), "short");
    EXPECT_EQ(bz::menu_label("0123456789abc", 10), "0123456...");
    EXPECT_EQ(bz::menu_label("\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9\xc3\xa9", 5),
              "\xc3\xa9\xc3\xa9...");
    EXPECT_EQ(bz::menu_label("a\nb", 10), "a\\nb");
    EXPECT_EQ(bz::menu_label(std::string(200, 'n'), 40).size(), 40u);
}
