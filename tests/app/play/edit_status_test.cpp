#include "app/play/edit_status.h"

#include <gtest/gtest.h>

namespace bz::app {
namespace {

level::Level two_boxes() {
    level::Level lv;
    level::ObjectDesc a;
    a.kind = "cube";
    a.position = {0, 0, -20};
    a.footprint_radius = 1.5;
    a.pos = {"/tmp/levels/test.toml", 7, 1};
    level::ObjectDesc b = a;
    b.kind = "pyramid";
    b.position = {0, 0, -40};
    b.pos.line = 12;
    lv.obstacles = {a, b};
    return lv;
}

TEST(EditStatus, NearestObjectOnTheRayIsPicked) {
    const level::Level lv = two_boxes();
    EXPECT_EQ(object_under_reticle(lv, {0, 1, 0}, {0, 0, -1}), 0u);
    EXPECT_EQ(object_under_reticle(lv, {0, 1, -30}, {0, 0, -1}), 1u);
    EXPECT_FALSE(object_under_reticle(lv, {0, 1, 0}, {0, 0, 1}));    // looking away
    EXPECT_FALSE(object_under_reticle(lv, {10, 1, 0}, {0, 0, -1}));  // beside them
    // Looking down at the ground before the first box: nothing.
    EXPECT_FALSE(object_under_reticle(lv, {0, 6, 0}, glm::normalize(glm::dvec3(0, -1, -0.5))));
    // High above, looking down onto the first box.
    EXPECT_EQ(object_under_reticle(lv, {0, 50, -20}, {0, -1, 0}), 0u);
}

TEST(EditStatus, LineNamesPositionHeadingAndTheObjectsFileLine) {
    const level::Level lv = two_boxes();
    const std::string s = edit_status_line(lv, {1, 2, 0}, 0.0, -5.0, {0, 0, -1});
    EXPECT_NE(s.find("X 1.0  Y 2.0  Z 0.0"), std::string::npos) << s;
    EXPECT_NE(s.find("HEADING 0"), std::string::npos) << s;
    EXPECT_NE(s.find("PITCH -5"), std::string::npos) << s;
    EXPECT_NE(s.find("AIM: CUBE  test.toml:7"), std::string::npos) << s;
    // Eye height 6 looks over the 3.75-high cube (2.5 footprint radii) to the pyramid.
    EXPECT_NE(edit_status_line(lv, {1, 6, 0}, 0.0, 0.0, {0, 0, -1}).find("AIM: NOTHING"),
              std::string::npos);
    // Yaw turns left; heading is a compass bearing (clockwise).
    EXPECT_NE(edit_status_line(lv, {}, 90.0, 0.0, {-1, 0, 0}).find("HEADING 270"),
              std::string::npos);
    EXPECT_NE(edit_status_line(lv, {}, 0.0, 0.0, {0, 0, 1}).find("AIM: NOTHING"),
              std::string::npos);
}

}  // namespace
}  // namespace bz::app
