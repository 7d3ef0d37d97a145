// Our interior-edge neighbours against meshoptimizer's adjacency index buffer on the same raw
// (unwelded) meshes. meshopt returns indices into the input vertices, ours into welded ones,
// so the comparison is by position.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

void expect_interior_neighbours_match_meshopt(const TriMesh& raw) {
    std::vector<unsigned> theirs(raw.indices.size() * 2);
    meshopt_generateAdjacencyIndexBuffer(theirs.data(), raw.indices.data(), raw.indices.size(),
                                         &raw.positions[0].x, raw.positions.size(),
                                         sizeof(glm::vec3));
    MeshReport report;
    const AdjacencyMesh ours = build_line_mesh(raw, &report);
    // Only meshes that lose no triangles keep a triangle-for-triangle correspondence.
    ASSERT_EQ(ours.triangle_count(), raw.triangle_count());
    std::size_t compared = 0;
    for (std::size_t i = 0; i < ours.adjacency.size(); i += 2) {
        EXPECT_EQ(ours.positions[ours.adjacency[i]], raw.positions[theirs[i]]);
        if (ours.edge_kinds[i / 2] != EdgeKind::interior) continue;
        EXPECT_EQ(ours.positions[ours.adjacency[i + 1]], raw.positions[theirs[i + 1]])
            << "triangle " << i / 6 << " edge " << (i / 2) % 3;
        ++compared;
    }
    EXPECT_GT(compared, 0u);
}

TEST(MeshoptCrossCheck, InteriorNeighboursAgree) {
    expect_interior_neighbours_match_meshopt(box({1, 2, 3}));
    expect_interior_neighbours_match_meshopt(open_box({1, 1, 1}));
    expect_interior_neighbours_match_meshopt(uv_sphere(1.0f, 24, 32));
    expect_interior_neighbours_match_meshopt(grid(40, 30, 0.5f, 8));
    expect_interior_neighbours_match_meshopt(cylinder(2.0f, 1.0f, 17));
    expect_interior_neighbours_match_meshopt(pyramid(1.0f, 1.5f));
}

}  // namespace
}  // namespace bz::geo
