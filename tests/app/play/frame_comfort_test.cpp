#include "app/play/frame_comfort.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace bz::app {
namespace {

TEST(FrameComfort, FlashLevelsToneDownOnlyTheOverdrive) {
    EXPECT_FLOAT_EQ(limit_flash(3.0f, "full"), 3.0f);
    EXPECT_FLOAT_EQ(limit_flash(2.5f, "soft"), 1.5f);
    EXPECT_FLOAT_EQ(limit_flash(2.5f, "off"), 1.0f);
    for (const char* level : {"full", "soft", "off"}) {
        EXPECT_FLOAT_EQ(limit_flash(0.7f, level), 0.7f) << "ordinary lines keep their brightness";
    }
}

TEST(FrameComfort, ColourSafeMovesRedToVioletAndKeepsGreen) {
    const glm::vec3 green{0.2f, 1.0f, 0.3f};
    EXPECT_EQ(colour_safe(green), green);
    const glm::vec3 red = colour_safe({1.0f, 0.22f, 0.15f});
    EXPECT_GT(red.b, red.g);
    EXPECT_GT(red.b, red.r);
    // Deuteranopia (Machado et al. 2009, severity 1): the two must stay apart in the
    // simulated picture; red and green themselves nearly collapse there.
    auto deutan = [](glm::vec3 c) {
        return glm::vec3(0.367322f * c.r + 0.860646f * c.g - 0.227968f * c.b,
                         0.280085f * c.r + 0.672501f * c.g + 0.047413f * c.b,
                         -0.011820f * c.r + 0.042940f * c.g + 0.968881f * c.b);
    };
    auto hue_gap = [&](glm::vec3 a, glm::vec3 b) {
        const glm::vec3 da = deutan(a) / std::max(1e-6f, glm::length(deutan(a)));
        const glm::vec3 db = deutan(b) / std::max(1e-6f, glm::length(deutan(b)));
        return glm::length(da - db);
    };
    const float before = hue_gap({1.0f, 0.22f, 0.15f}, green);
    const float after = hue_gap(red, green);
    EXPECT_GT(after, 3.0f * before) << before << " -> " << after;
}

TEST(FrameComfort, AppliesToSceneAndHud) {
    scene::FrameList f;
    scene::DrawItem debris;
    debris.intensity = 3.0f;
    debris.color = {1.0f, 0.5f, 0.3f};
    f.items.push_back(debris);
    f.hud.push_back({{0, 0}, {1, 1}, {1.0f, 0.22f, 0.15f}, 2.5f});
    apply_comfort(f, "off", true);
    EXPECT_FLOAT_EQ(f.items[0].intensity, 1.0f);
    EXPECT_FLOAT_EQ(f.hud[0].intensity, 1.0f);
    EXPECT_GT(f.items[0].color.b, f.items[0].color.r);
    EXPECT_GT(f.hud[0].color.b, f.hud[0].color.r);
}

}  // namespace
}  // namespace bz::app
