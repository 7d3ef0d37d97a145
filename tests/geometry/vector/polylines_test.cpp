#include "geometry/vector/polylines.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/vector/path_order.h"

namespace {

using bz::geo::chain_segments;
using bz::geo::LineKind;
using bz::geo::Polyline;
using bz::geo::VisibleSegment;

VisibleSegment seg(double ax, double ay, double bx, double by, LineKind kind = LineKind::silhouette,
                   std::uint32_t instance = 0) {
    return {{ax, ay}, {bx, by}, kind, instance};
}

std::size_t segment_count(const std::vector<Polyline>& lines) {
    std::size_t n = 0;
    for (const Polyline& l : lines) n += l.points.size() - 1;
    return n;
}

TEST(ChainSegments, JoinsAnOpenRunInEitherDirection) {
    // Three segments of one run, given out of order and with one reversed.
    const std::vector<VisibleSegment> s = {seg(1, 0, 2, 0), seg(3, 1, 2, 0), seg(0, 0, 1, 0)};
    const auto lines = chain_segments(s, 0.01);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(lines[0].points.size(), 4u);
    const glm::dvec2 a = lines[0].points.front(), b = lines[0].points.back();
    EXPECT_TRUE((a == glm::dvec2(0, 0) && b == glm::dvec2(3, 1)) ||
                (a == glm::dvec2(3, 1) && b == glm::dvec2(0, 0)));
}

TEST(ChainSegments, ClosesALoop) {
    const std::vector<VisibleSegment> s = {seg(0, 0, 1, 0), seg(1, 0, 1, 1), seg(1, 1, 0, 1),
                                           seg(0, 1, 0, 0)};
    const auto lines = chain_segments(s, 0.0);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].points.size(), 5u);
    EXPECT_EQ(lines[0].points.front(), lines[0].points.back());
}

TEST(ChainSegments, JoinsWithinTheToleranceOnly) {
    const std::vector<VisibleSegment> s = {seg(0, 0, 1, 0), seg(1.005, 0, 2, 0), seg(2.5, 0, 3, 0)};
    const auto lines = chain_segments(s, 0.01);
    EXPECT_EQ(lines.size(), 2u);
    EXPECT_EQ(segment_count(lines), 3u);
    // The merged end moved by no more than the tolerance.
    for (const Polyline& l : lines)
        for (const glm::dvec2& p : l.points)
            EXPECT_TRUE(std::abs(p.x - 1.0) < 0.011 || std::abs(p.x - 0.0) < 1e-12 ||
                        std::abs(p.x - 2.0) < 1e-12 || std::abs(p.x - 2.5) < 1e-12 ||
                        std::abs(p.x - 3.0) < 1e-12);
}

TEST(ChainSegments, EndsAtJunctionsAndKeepsKindsAndInstancesApart) {
    // A T junction: three runs meet at (1, 0).
    std::vector<VisibleSegment> s = {seg(0, 0, 1, 0), seg(1, 0, 2, 0), seg(1, 0, 1, 1)};
    EXPECT_EQ(chain_segments(s, 0.01).size(), 3u);
    // Two segments meeting end to end, of different kinds or objects, stay apart.
    s = {seg(0, 0, 1, 0), seg(1, 0, 2, 0, LineKind::crease)};
    EXPECT_EQ(chain_segments(s, 0.01).size(), 2u);
    s = {seg(0, 0, 1, 0), seg(1, 0, 2, 0, LineKind::silhouette, 1)};
    const auto lines = chain_segments(s, 0.01);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NE(lines[0].instance, lines[1].instance);
}

TEST(ChainSegments, KeepsEverySegmentIncludingDotsAndDuplicates) {
    const std::vector<VisibleSegment> s = {seg(5, 5, 5, 5), seg(0, 0, 1, 0), seg(0, 0, 1, 0),
                                           seg(7, 7, 7.001, 7)};
    const auto lines = chain_segments(s, 0.01);
    EXPECT_EQ(segment_count(lines), 4u);
}

TEST(ChainSegments, RefusesABadTolerance) {
    const std::vector<VisibleSegment> s = {seg(0, 0, 1, 0)};
    EXPECT_THROW(chain_segments(s, -1.0), std::invalid_argument);
    EXPECT_THROW(chain_segments(s, NAN), std::invalid_argument);
    const std::vector<VisibleSegment> bad = {seg(0, 0, INFINITY, 0)};
    EXPECT_THROW(chain_segments(bad, 0.01), std::invalid_argument);
    EXPECT_TRUE(chain_segments({}, 0.01).empty());
}

TEST(OrderNearestEnd, VisitsTheNearestEndAndReversesPaths) {
    // Paths along the x axis, shuffled, one reversed: the greedy order from the origin walks
    // them left to right with no pen-up travel beyond the gaps.
    std::vector<Polyline> paths;
    for (int i : {3, 0, 4, 1, 2}) {
        Polyline p;
        p.points = {{i * 2.0, 0.0}, {i * 2.0 + 1.0, 0.0}};
        if (i == 2) std::reverse(p.points.begin(), p.points.end());
        paths.push_back(p);
    }
    const double before = bz::geo::pen_up_travel(paths);
    const glm::dvec2 pen = bz::geo::order_nearest_end(paths, {0.0, 0.0});
    EXPECT_EQ(pen, glm::dvec2(9.0, 0.0));
    for (std::size_t i = 0; i < paths.size(); ++i)
        EXPECT_EQ(paths[i].points.front(), glm::dvec2(static_cast<double>(i) * 2.0, 0.0));
    EXPECT_DOUBLE_EQ(bz::geo::pen_up_travel(paths), 4.0);
    EXPECT_GT(before, 4.0);
}

TEST(OrderNearestEnd, MatchesABruteForceGreedyOnScatteredPaths) {
    std::vector<Polyline> paths;
    std::uint32_t state = 12345;
    auto next = [&] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / static_cast<double>(1u << 24) * 500.0;
    };
    for (int i = 0; i < 400; ++i) {
        Polyline p;
        const glm::dvec2 a(next(), next() * 0.3);  // a wide, flat spread
        p.points = {a, a + glm::dvec2(next() * 0.01, next() * 0.01)};
        paths.push_back(p);
    }
    std::vector<Polyline> brute = paths, fast = paths;
    glm::dvec2 pen(-10.0, -10.0);
    std::vector<Polyline> expected;
    while (!brute.empty()) {
        std::size_t best = 0;
        bool rev = false;
        double d = 1e300;
        for (std::size_t i = 0; i < brute.size(); ++i) {
            const double df = glm::length(brute[i].points.front() - pen);
            const double db = glm::length(brute[i].points.back() - pen);
            if (df < d) d = df, best = i, rev = false;
            if (db < d) d = db, best = i, rev = true;
        }
        Polyline p = brute[best];
        if (rev) std::reverse(p.points.begin(), p.points.end());
        pen = p.points.back();
        expected.push_back(p);
        brute.erase(brute.begin() + static_cast<long>(best));
    }
    bz::geo::order_nearest_end(fast, {-10.0, -10.0});
    EXPECT_NEAR(bz::geo::pen_up_travel(fast), bz::geo::pen_up_travel(expected), 1e-9);
    EXPECT_LT(bz::geo::pen_up_travel(fast), bz::geo::pen_up_travel(paths) * 0.2);
}

}  // namespace
