// Settings files built to hurt: keys nested thousands of levels deep (toml++ recursed once
// per level and overflowed the stack), thousands of unknown keys, and control characters in
// key names. Each gives positioned, bounded, escaped messages and the defaults.
#include <gtest/gtest.h>

#include <string>

#include "platform/settings.h"
#include "platform/settings_test_util.h"

namespace bz::platform {
namespace {

using test::kPresets;
using test::kStyles;
using test::parse;

std::string repeat(const std::string& part, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += part;
    return out;
}

TEST(SettingsDeepKeys, DeepDottedKeyIsRefusedWithPosition) {
    const SettingsLoad r = parse("volume = 0.5\n  a" + repeat(".a", 40000) + " = 1\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].rfind("settings.toml:2:3: error: key is nested more than", 0), 0u)
        << r.errors[0];
    EXPECT_FALSE(r.may_save());
    EXPECT_EQ(r.settings.volume, Settings{}.volume);
}

TEST(SettingsDeepKeys, DeepTableHeaderAndQuotedPartsAreRefused) {
    EXPECT_FALSE(parse("[a" + repeat(".b", 5000) + "]\n").errors.empty());
    EXPECT_FALSE(parse("[[a" + repeat(".\"b\"", 5000) + "]]\n").errors.empty());
    EXPECT_FALSE(parse("x = {a" + repeat(".b", 5000) + " = 1}\n").errors.empty());
}

// Accented letters typed without quotes once sent toml++ 3.3.0 down an unreachable path
// (core/text/toml.h); now each is a positioned error and the defaults stand.
TEST(SettingsNonAscii, AccentOutsideQuotesIsAPositionedError) {
    const SettingsLoad r = parse("volume = 0.4\nstyle = caf\xC3\xA9\n");
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors[0].rfind("settings.toml:2:", 0), 0u) << r.errors[0];
    EXPECT_FALSE(r.may_save());
    const SettingsLoad combining = parse("volume = 0.5\xCC\x9C\n");
    ASSERT_FALSE(combining.errors.empty());
    EXPECT_EQ(combining.errors[0].rfind("settings.toml:1:13:", 0), 0u) << combining.errors[0];
    EXPECT_EQ(combining.settings.volume, Settings{}.volume);
}

TEST(SettingsDeepKeys, DotsInStringsAndNumbersAreFine) {
    const SettingsLoad r = parse("volume = 0.5\nstyle = \"" + repeat("a.", 100) + "\"\n");
    ASSERT_EQ(r.errors.size(), 1u);  // only the bad style value
    EXPECT_NE(r.errors[0].find("style must be one of"), std::string::npos);
}

TEST(SettingsNonAscii, NonAsciiOutsideStringsIsASyntaxError) {
    const SettingsLoad r = parse("volume = 0.5\n\xc3\xa9 = 1\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].rfind("settings.toml:2:1: error: syntax error", 0), 0u) << r.errors[0];
}

TEST(SettingsUnknownKeys, MessagesStopAtOneHundred) {
    std::string text;
    for (int i = 0; i < 20000; ++i) text += "junk" + std::to_string(i) + " = 1\n";
    const SettingsLoad r = parse(text);
    ASSERT_EQ(r.errors.size(), 100u);
    EXPECT_EQ(r.errors[0], "settings.toml:1:1: error: unknown setting 'junk0'");
    EXPECT_EQ(r.errors[99], "settings.toml: error: 19901 more errors not shown");
}

TEST(SettingsUntrustedText, ControlCharactersInKeysAreEscaped) {
    const SettingsLoad r = parse(
        "\"bad\\u001b[2Jkey\\nx\" = 1\n[keys]\n\"f\\u0000ire\" = [\"Space\"]\n"
        "fire = [\"\\u001b]0;x\"]\n");
    ASSERT_EQ(r.errors.size(), 3u);
    for (const std::string& e : r.errors) {
        for (const char c : e) EXPECT_GE(static_cast<unsigned char>(c), 0x20u) << e;
    }
    EXPECT_NE(r.errors[0].find("'bad\\e[2Jkey\\nx'"), std::string::npos) << r.errors[0];
}

TEST(SettingsUntrustedText, HugeKeyNameIsCut) {
    const SettingsLoad r = parse(std::string(100000, 'k') + " = 1\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_LT(r.errors[0].size(), 400u);
}

TEST(SettingsEmptyInput, BrokenFileIsReportedFromLineOne) {
    const SettingsLoad r = parse("[");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].rfind("settings.toml:1:", 0), 0u) << r.errors[0];
}

}  // namespace
}  // namespace bz::platform
