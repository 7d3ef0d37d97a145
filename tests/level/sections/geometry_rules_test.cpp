// The kinds table, footprint geometry and "did you mean" suggestions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "level/kinds.h"
#include "level/sections/placement.h"
#include "level/sections/suggest.h"

namespace bz::level {
namespace {

TEST(Kinds, FootprintRadiusHoldsTheBase) {
    for (const auto& k : builtin_kinds()) {
        if (k.shape == KindShape::model) continue;
        EXPECT_NEAR(k.footprint_radius, std::hypot(k.half_x, k.half_z), 1e-12) << k.name;
        EXPECT_GT(k.height, 0.0) << k.name;
    }
}

TEST(Kinds, TheIssuesKindsExist) {
    for (const char* name : {"cube", "pyramid", "tall_box", "short_box", "model"}) {
        EXPECT_NE(find_kind(name), nullptr) << name;
    }
    EXPECT_EQ(find_kind("sphere"), nullptr);
}

TEST(Placement, BoxDistanceFollowsHeading) {
    ObjectDesc wall;
    wall.kind = "wall";
    wall.position = {0, 0, 0};
    const BuiltinKind& k = *find_kind("wall");  // 20 long (x), 1 thick (z)
    EXPECT_DOUBLE_EQ(footprint_distance(wall, k, {12, 0, 0}, 400, false), 2.0);
    EXPECT_DOUBLE_EQ(footprint_distance(wall, k, {5, 0, 0}, 400, false), 0.0);
    wall.heading_deg = 90.0;  // now 20 long along z
    EXPECT_NEAR(footprint_distance(wall, k, {12, 0, 0}, 400, false), 11.5, 1e-9);
    EXPECT_NEAR(footprint_distance(wall, k, {0, 0, 12}, 400, false), 2.0, 1e-9);
    wall.scale = 2.0;
    EXPECT_NEAR(footprint_distance(wall, k, {0, 0, 25}, 400, false), 5.0, 1e-9);
}

TEST(Placement, ModelIsACircleAndTheFieldWraps) {
    ObjectDesc m;
    m.kind = "model";
    m.position = {195, 0, 0};
    m.footprint_radius = 4.0;
    const BuiltinKind& k = *find_kind("model");
    EXPECT_NEAR(footprint_distance(m, k, {-195, 0, 0}, 400, true), 6.0, 1e-9);
    EXPECT_NEAR(footprint_distance(m, k, {-195, 0, 0}, 400, false), 386.0, 1e-9);
    EXPECT_EQ(ground_delta({195, 0, 195}, {-195, 0, -195}, 400, true), glm::dvec2(10, 10));
}

TEST(Suggest, EditDistance) {
    EXPECT_EQ(edit_distance("wrap", "wrap"), 0u);
    EXPECT_EQ(edit_distance("wrapp", "wrap"), 1u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
    EXPECT_EQ(edit_distance("", "abc"), 3u);
    EXPECT_EQ(edit_distance("Size", "size"), 0u);
}

TEST(Suggest, ClosestOnlyWhenClose) {
    constexpr std::array<std::string_view, 4> keys = {"size", "wrap", "obstacle_color", "heading"};
    EXPECT_EQ(closest("wrp", keys), "wrap");
    EXPECT_EQ(closest("obstacle_colour", keys), "obstacle_color");
    EXPECT_EQ(closest("SIZE", keys), "size");
    EXPECT_EQ(closest("q", keys), "");
    EXPECT_EQ(closest("elephant", keys), "");
    EXPECT_EQ(closest(std::string(1000, 'x'), keys), "");
    EXPECT_EQ(did_you_mean("headin", keys), "; did you mean 'heading'?");
}

}  // namespace
}  // namespace bz::level
