// The `difficulty` setting: "level" (each level's own) by default, one of easy, normal or
// arcade when set, a bad value reported at its position and the default kept.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "platform/settings.h"
#include "platform/settings_test_util.h"

namespace bz::platform {
namespace {

using test::kPresets;
using test::kStyles;

TEST(SettingsDifficulty, DefaultLetsTheLevelChoose) {
    const SettingsLoad s = parse_settings("", "settings.toml", {kPresets, kStyles});
    EXPECT_TRUE(s.errors.empty());
    EXPECT_EQ(s.settings.difficulty, "level");
    EXPECT_NE(format_settings(s.settings).find("difficulty = \"level\""), std::string::npos);
}

TEST(SettingsDifficulty, ReadsEachChoiceAndWritesItBack) {
    for (const std::string d : {"easy", "normal", "arcade", "level"}) {
        const SettingsLoad s =
            parse_settings("difficulty = \"" + d + "\"\n", "settings.toml", {kPresets, kStyles});
        EXPECT_TRUE(s.errors.empty()) << d;
        EXPECT_EQ(s.settings.difficulty, d);
        const SettingsLoad again =
            parse_settings(format_settings(s.settings), "settings.toml", {kPresets, kStyles});
        EXPECT_TRUE(again.errors.empty());
        EXPECT_EQ(again.settings.difficulty, d);
    }
}

TEST(SettingsDifficulty, BadValueIsReportedAndKeepsTheDefault) {
    const SettingsLoad s =
        parse_settings("difficulty = \"brutal\"\n", "settings.toml", {kPresets, kStyles});
    ASSERT_EQ(s.errors.size(), 1u);
    EXPECT_NE(s.errors[0].find("settings.toml:1:"), std::string::npos) << s.errors[0];
    EXPECT_NE(s.errors[0].find("difficulty"), std::string::npos) << s.errors[0];
    EXPECT_EQ(s.settings.difficulty, "level");
    EXPECT_FALSE(s.may_save());
}

}  // namespace
}  // namespace bz::platform
