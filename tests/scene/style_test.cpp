// Style names: canonical names round-trip, the old names still work, the play key cycles
// through every style and wraps around.
#include "scene/style.h"

#include <gtest/gtest.h>

#include <set>

using bz::scene::Style;

TEST(Style, CanonicalNamesRoundTrip) {
    std::set<std::string_view> seen;
    for (const Style s : bz::scene::all_styles()) {
        const std::string_view name = bz::scene::style_name(s);
        EXPECT_TRUE(seen.insert(name).second) << name;
        EXPECT_EQ(bz::scene::style_from_name(name), s) << name;
    }
    EXPECT_EQ(seen.size(), 7u);
    EXPECT_EQ(bz::scene::style_name_list(),
              "vector, vector-xray, toon, sketch, pop-art, halo or technical");
}

TEST(Style, OldNamesMeanTheVectorStyles) {
    EXPECT_EQ(bz::scene::style_from_name("occluded"), Style::vector);
    EXPECT_EQ(bz::scene::style_from_name("arcade"), Style::vector_xray);
    EXPECT_EQ(bz::scene::style_name(Style::arcade), "vector-xray");
    EXPECT_FALSE(bz::scene::style_from_name("Toon").has_value());
    EXPECT_FALSE(bz::scene::style_from_name("").has_value());
    EXPECT_EQ(bz::scene::accepted_style_names().size(), 9u);
}

TEST(Style, NextStyleVisitsEveryStyleThenWraps) {
    Style s = Style::vector;
    std::set<Style> visited;
    for (std::size_t i = 0; i < bz::scene::all_styles().size(); ++i) {
        visited.insert(s);
        s = bz::scene::next_style(s);
    }
    EXPECT_EQ(visited.size(), bz::scene::all_styles().size());
    EXPECT_EQ(s, Style::vector);
}
