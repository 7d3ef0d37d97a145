#include "scene/shapes.h"

#include <gtest/gtest.h>

#include <map>
#include <utility>

namespace bz::scene::shapes {
namespace {

// Every directed edge appears once and its reverse once: closed and consistently wound.
bool closed_and_consistent(const geo::TriMesh& m) {
    std::map<std::pair<glm::vec3, glm::vec3>, int,
             bool (*)(const std::pair<glm::vec3, glm::vec3>&,
                      const std::pair<glm::vec3, glm::vec3>&)>
        edges(
            [](const std::pair<glm::vec3, glm::vec3>& a, const std::pair<glm::vec3, glm::vec3>& b) {
                auto key = [](const std::pair<glm::vec3, glm::vec3>& e) {
                    return std::make_tuple(e.first.x, e.first.y, e.first.z, e.second.x, e.second.y,
                                           e.second.z);
                };
                return key(a) < key(b);
            });
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 a = m.positions[m.indices[t + k]];
            const glm::vec3 b = m.positions[m.indices[t + (k + 1) % 3]];
            ++edges[{a, b}];
        }
    }
    for (const auto& [e, n] : edges) {
        if (n != 1) return false;
        auto rev = edges.find({e.second, e.first});
        if (rev == edges.end() || rev->second != 1) return false;
    }
    return true;
}

TEST(Shapes, BoxIsClosedOutwardWithTheRightVolume) {
    const geo::TriMesh b = box({-1, 0, -2}, {1, 3, 2});
    EXPECT_EQ(b.triangle_count(), 12u);
    EXPECT_TRUE(closed_and_consistent(b));
    EXPECT_NEAR(signed_volume(b), 2.0 * 3.0 * 4.0, 1e-4);
}

TEST(Shapes, LoftWithApexesIsClosedAndOutward) {
    // A pyramid (ring + apex) and a double cone (apex, ring, apex).
    const geo::TriMesh pyr = loft({rect_ring(2, 2, 0), Ring{{{0, 0}}, 3}});
    EXPECT_TRUE(closed_and_consistent(pyr));
    EXPECT_NEAR(signed_volume(pyr), 4.0 * 3.0 / 3.0, 1e-4);
    const geo::TriMesh dbl =
        loft({Ring{{{0, 0}}, -1}, ellipse_ring(8, {1, 1}, 0), Ring{{{0, 0}}, 1}});
    EXPECT_TRUE(closed_and_consistent(dbl));
    EXPECT_GT(signed_volume(dbl), 0.0);
}

TEST(Shapes, LoftRejectsBadRings) {
    EXPECT_THROW(loft({rect_ring(1, 1, 0)}), std::invalid_argument);
    EXPECT_THROW(loft({rect_ring(1, 1, 0), ellipse_ring(5, {1, 1}, 1)}), std::invalid_argument);
    EXPECT_THROW(loft({Ring{{{0, 0}}, 0}, Ring{{{0, 0}}, 1}}), std::invalid_argument);
}

TEST(Shapes, StripFacesTheViewerAndRingsClose) {
    // Lower line left to right along +x, upper above: faces +z.
    const geo::TriMesh s =
        strip({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}}, false);
    ASSERT_EQ(s.triangle_count(), 4u);
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const glm::vec3 a = s.positions[s.indices[t]];
        const glm::vec3 b = s.positions[s.indices[t + 1]];
        const glm::vec3 c = s.positions[s.indices[t + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
    }
    const geo::TriMesh ring =
        strip({{0, 0, 0}, {1, 0, 0}, {1, 0, 1}}, {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}}, true);
    EXPECT_EQ(ring.triangle_count(), 6u);
}

TEST(Shapes, AppendTransforms) {
    geo::TriMesh m;
    append(m, box({0, 0, 0}, {1, 1, 1}));
    append(m, box({0, 0, 0}, {1, 1, 1}), glm::mat4(2.0f));
    EXPECT_EQ(m.positions.size(), 16u);
    EXPECT_NEAR(signed_volume(m), 1.0 + 8.0, 1e-4);
}

}  // namespace
}  // namespace bz::scene::shapes
