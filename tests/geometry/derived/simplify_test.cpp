#include "geometry/derived/simplify.h"

#include <gtest/gtest.h>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

TEST(Simplify, DenseMeshGetsFewerTrianglesWithinItsBounds) {
    const AdjacencyMesh sphere = build_line_mesh(uv_sphere(1.0f, 32, 64));
    const auto reduced = simplify_line_mesh(sphere);
    ASSERT_TRUE(reduced);
    EXPECT_LT(reduced->triangle_count(), sphere.triangle_count() * 7 / 10);
    EXPECT_GT(reduced->triangle_count(), 16u);
    // Still a closed surface: every edge interior, adjacency complete.
    EXPECT_EQ(reduced->adjacency.size(), reduced->triangle_count() * 6);
    for (EdgeKind k : reduced->edge_kinds) EXPECT_EQ(k, EdgeKind::interior);
    const Bounds a = compute_bounds(sphere.positions), b = compute_bounds(reduced->positions);
    for (int i = 0; i < 3; ++i) {
        EXPECT_LE(b.max[i], a.max[i] + 1e-6f);
        EXPECT_GE(b.min[i], a.min[i] - 1e-6f);
        EXPECT_GT(b.max[i], a.max[i] - 0.1f);  // within the 2% error budget, roughly
    }
}

TEST(Simplify, SmallMeshesAreLeftAlone) {
    EXPECT_FALSE(simplify_line_mesh(build_line_mesh(box({1, 1, 1}))));
    // A flat grid keeps its boundary: open edges are feature lines and must not move.
    const AdjacencyMesh g = build_line_mesh(grid(16, 16, 1.0f, 16));
    const auto r = simplify_line_mesh(g);
    ASSERT_TRUE(r);
    const Bounds a = compute_bounds(g.positions), b = compute_bounds(r->positions);
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.max, b.max);
}

}  // namespace
}  // namespace bz::geo
