#include "scene/camera_check.h"

#include <gtest/gtest.h>

namespace bz::scene {
namespace {

const glm::dvec3 kUp{0.0, 1.0, 0.0};

TEST(PathViewProblem, GoodKeysWithAGoodPathPass) {
    EXPECT_EQ(path_view_problem({0, 5, 0}, {0, 0, 50}, {10, 5, 0}, {50, 0, 0}, kUp), "");
    // Both ends steep but on the same side: the path never looks straight down.
    EXPECT_EQ(path_view_problem({0, 50, 0}, {1, 0, 0}, {0, 50, 0}, {1, 0, 1}, kUp), "");
}

TEST(PathViewProblem, APathThroughStraightDownBetweenGoodKeysIsFound) {
    // Above the field, looking down and ahead, then down and behind: halfway the view is
    // along the up axis. Each key alone is a good view.
    const glm::dvec3 eye{0, 50, 0}, ahead{0, 0, 10}, behind{0, 0, -10};
    ASSERT_EQ(view_problem(eye, ahead, kUp), "");
    ASSERT_EQ(view_problem(eye, behind, kUp), "");
    double at = -1.0;
    const std::string why = path_view_problem(eye, ahead, eye, behind, kUp, &at);
    EXPECT_NE(why.find("parallel to the up vector"), std::string::npos) << why;
    EXPECT_NEAR(at, 0.5, 1e-9);
    // Off-centre ends and a moving eye: the crossing is found wherever it falls.
    const std::string moving =
        path_view_problem({0, 40, 0}, {3, 0, 9}, {6, 60, 0}, {3, 0, -9}, kUp, &at);
    EXPECT_NE(moving.find("parallel to the up vector"), std::string::npos) << moving;
    EXPECT_GT(at, 0.0);
    EXPECT_LT(at, 1.0);
}

TEST(PathViewProblem, AnEyePassingThroughTheTargetIsFound) {
    double at = -1.0;
    const std::string why =
        path_view_problem({0, 5, -10}, {0, 5, 0}, {0, 5, 10}, {0, 5, 0}, kUp, &at);
    EXPECT_NE(why.find("eye is at the target"), std::string::npos) << why;
    EXPECT_NEAR(at, 0.5, 1e-9);
}

TEST(PathViewProblem, ABadKeyIsReportedAtItsEnd) {
    double at = -1.0;
    EXPECT_NE(path_view_problem({0, 5, 0}, {0, 0, 50}, {0, 50, 0}, {0, 0, 0}, kUp, &at), "");
    EXPECT_EQ(at, 1.0);
}

}  // namespace
}  // namespace bz::scene
