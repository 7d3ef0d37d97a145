#include "geometry/generated/primitives.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace bz::geo {
namespace {

glm::vec3 normal_of(const TriMesh& m, std::size_t t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]];
    return glm::cross(m.positions[m.indices[3 * t + 1]] - a, m.positions[m.indices[3 * t + 2]] - a);
}

glm::vec3 centre_of(const TriMesh& m, std::size_t t) {
    return (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
            m.positions[m.indices[3 * t + 2]]) /
           3.0f;
}

// Counter-clockwise seen from outside: every face normal points away from `inside`.
void expect_faces_outward(const TriMesh& m, glm::vec3 inside) {
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        EXPECT_GT(glm::dot(normal_of(m, t), centre_of(m, t) - inside), 0.0f) << "triangle " << t;
    }
}

TEST(Primitives, BoxIsSplitPerFaceAndFacesOutward) {
    const glm::vec3 half(1.0f, 2.0f, 3.0f);
    const TriMesh b = box(half);
    EXPECT_EQ(b.positions.size(), 24u);
    EXPECT_EQ(b.triangle_count(), 12u);
    expect_faces_outward(b, glm::vec3(0.0f));
    const Bounds bounds = compute_bounds(b.positions);
    EXPECT_EQ(bounds.min, -half);
    EXPECT_EQ(bounds.max, half);
}

TEST(Primitives, OpenBoxLacksOnlyTheTop) {
    const TriMesh b = open_box({1, 1, 1});
    EXPECT_EQ(b.positions.size(), 20u);
    EXPECT_EQ(b.triangle_count(), 10u);
    expect_faces_outward(b, glm::vec3(0.0f));
    for (std::size_t t = 0; t < b.triangle_count(); ++t) EXPECT_LE(normal_of(b, t).y, 0.0f);
}

TEST(Primitives, SphereHasDuplicatedSeamAndPoles) {
    const std::uint32_t rings = 6, segments = 8;
    const TriMesh s = uv_sphere(2.0f, rings, segments);
    EXPECT_EQ(s.positions.size(), (rings + 1u) * (segments + 1u));
    EXPECT_EQ(s.triangle_count(), 2u * segments * (rings - 1));
    expect_faces_outward(s, glm::vec3(0.0f));
    const std::uint32_t cols = segments + 1;
    for (std::uint32_t i = 0; i <= rings; ++i) {
        EXPECT_EQ(s.positions[i * cols], s.positions[i * cols + segments]);  // seam column
    }
    for (std::uint32_t j = 0; j <= segments; ++j) {
        EXPECT_EQ(s.positions[j], glm::vec3(0.0f, 2.0f, 0.0f));
        EXPECT_EQ(s.positions[rings * cols + j], glm::vec3(0.0f, -2.0f, 0.0f));
    }
}

TEST(Primitives, GridTilesDuplicateTheirBorders) {
    const std::uint32_t nx = 5, nz = 3, tile = 2;
    const TriMesh g = grid(nx, nz, 2.0f, tile);
    EXPECT_EQ(g.triangle_count(), 2u * nx * nz);
    // Tiles are 2, 2, 1 cells wide and 2, 1 deep: (3+3+2) x (3+2) vertices.
    EXPECT_EQ(g.positions.size(), 8u * 5u);
    for (std::size_t t = 0; t < g.triangle_count(); ++t) EXPECT_GT(normal_of(g, t).y, 0.0f);
    const Bounds b = compute_bounds(g.positions);
    EXPECT_EQ(b.min, glm::vec3(-5.0f, 0.0f, -3.0f));
    EXPECT_EQ(b.max, glm::vec3(5.0f, 0.0f, 3.0f));
}

TEST(Primitives, PyramidAndCylinderFaceOutward) {
    const TriMesh p = pyramid(1.0f, 2.0f);
    EXPECT_EQ(p.triangle_count(), 6u);
    expect_faces_outward(p, glm::vec3(0.0f, 0.5f, 0.0f));
    const TriMesh c = cylinder(1.0f, 0.5f, 12);
    EXPECT_EQ(c.triangle_count(), 48u);
    expect_faces_outward(c, glm::vec3(0.0f));
}

TEST(Primitives, FinIsThreeQuadsOnOneEdge) {
    const TriMesh f = fin();
    EXPECT_EQ(f.triangle_count(), 6u);
    std::size_t on_shared_edge = 0;
    for (std::size_t t = 0; t < f.triangle_count(); ++t) {
        int corners_on_axis = 0;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 p = f.positions[f.indices[3 * t + k]];
            corners_on_axis += (p.x == 0.0f && p.z == 0.0f) ? 1 : 0;
        }
        on_shared_edge += corners_on_axis == 2 ? 1 : 0;
    }
    EXPECT_EQ(on_shared_edge, 3u);
}

TEST(Primitives, TwinFacedAddsReversedCopies) {
    const TriMesh b = box({1, 1, 1});
    const TriMesh t = twin_faced(b);
    ASSERT_EQ(t.triangle_count(), 24u);
    EXPECT_EQ(t.positions.size(), 48u);
    for (std::size_t i = 0; i < 12; ++i) {
        EXPECT_EQ(normal_of(t, 12 + i), -normal_of(t, i));
    }
}

TEST(Primitives, RejectInvalidSizes) {
    EXPECT_THROW(box({0, 1, 1}), std::invalid_argument);
    EXPECT_THROW(uv_sphere(1.0f, 1, 8), std::invalid_argument);
    EXPECT_THROW(uv_sphere(1.0f, 4, 2), std::invalid_argument);
    EXPECT_THROW(grid(4, 4, 1.0f, 0), std::invalid_argument);
    EXPECT_THROW(cylinder(1.0f, -1.0f, 8), std::invalid_argument);
    EXPECT_THROW(pyramid(1.0f, 0.0f), std::invalid_argument);
}

}  // namespace
}  // namespace bz::geo
