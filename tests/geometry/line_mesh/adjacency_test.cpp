#include "geometry/line_mesh/adjacency.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "core/rng.h"
#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"
#include "reference_adjacency.h"

namespace bz::geo {
namespace {

using test::count_kind;

void expect_matches_reference(const std::vector<std::uint32_t>& tri, std::size_t vertices) {
    const Adjacency adj = build_adjacency(tri, vertices);
    const test::ReferenceAdjacency ref = test::reference_adjacency(tri);
    EXPECT_EQ(adj.adjacency, ref.adjacency);
    EXPECT_EQ(adj.edge_kinds, ref.kinds);
}

// True when (a, b, c) in this winding (any rotation) is a triangle of the mesh.
bool has_triangle(const AdjacencyMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    for (std::size_t i = 0; i < m.triangles.size(); i += 3) {
        for (std::size_t r = 0; r < 3; ++r) {
            if (m.triangles[i + r] == a && m.triangles[i + (r + 1) % 3] == b &&
                m.triangles[i + (r + 2) % 3] == c) {
                return true;
            }
        }
    }
    return false;
}

TEST(Adjacency, ClosedCubeHasOnlyInteriorEdgesWithTrueNeighbours) {
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(box({1.0f, 2.0f, 3.0f}), &report);
    ASSERT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.positions.size(), 8u);
    EXPECT_EQ(report.boundary_edges, 0u);
    ASSERT_EQ(m.adjacency.size(), 72u);
    for (std::size_t t = 0; t < 12; ++t) {
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t v0 = m.triangles[3 * t + e];
            const std::uint32_t v1 = m.triangles[3 * t + (e + 1) % 3];
            const std::uint32_t opposite = m.adjacency[6 * t + 2 * e + 1];
            EXPECT_EQ(m.edge_kinds[3 * t + e], EdgeKind::interior);
            EXPECT_EQ(m.adjacency[6 * t + 2 * e], v0);
            EXPECT_NE(opposite, v0);
            EXPECT_NE(opposite, v1);
            // The neighbour runs the shared edge the other way and has `opposite` as third
            // corner.
            EXPECT_TRUE(has_triangle(m, v1, v0, opposite)) << "triangle " << t << " edge " << e;
        }
    }
}

TEST(Adjacency, OpenBoxHasExactlyTheFourRimEdgesAsBoundary) {
    const glm::vec3 half(1.0f, 0.5f, 2.0f);
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(open_box(half), &report);
    EXPECT_EQ(report.boundary_edges, 4u);
    ASSERT_EQ(count_kind(m.edge_kinds, EdgeKind::boundary), 4u);
    for (std::size_t h = 0; h < m.edge_kinds.size(); ++h) {
        if (m.edge_kinds[h] != EdgeKind::boundary) continue;
        const std::size_t next = h % 3 == 2 ? h - 2 : h + 1;
        EXPECT_EQ(m.positions[m.triangles[h]].y, half.y);
        EXPECT_EQ(m.positions[m.triangles[next]].y, half.y);
        EXPECT_EQ(m.adjacency[2 * h + 1], m.triangles[h]);  // degenerate neighbour
    }
    EXPECT_EQ(count_kind(m.edge_kinds, EdgeKind::interior), m.edge_kinds.size() - 4);
}

TEST(Adjacency, FinEdgeIsNonManifoldOnAllThreeFaces) {
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(fin(), &report);
    EXPECT_EQ(report.non_manifold_edges, 1u);
    EXPECT_EQ(report.boundary_edges, 9u);
    ASSERT_EQ(count_kind(m.edge_kinds, EdgeKind::non_manifold), 3u);
    EXPECT_EQ(count_kind(m.edge_kinds, EdgeKind::interior), 6u);
    for (std::size_t h = 0; h < m.edge_kinds.size(); ++h) {
        if (m.edge_kinds[h] != EdgeKind::non_manifold) continue;
        const std::size_t next = h % 3 == 2 ? h - 2 : h + 1;
        // The shared edge is (0,0,0)-(0,1,0).
        EXPECT_EQ(m.positions[m.triangles[h]].x, 0.0f);
        EXPECT_EQ(m.positions[m.triangles[next]].x, 0.0f);
        EXPECT_EQ(m.adjacency[2 * h + 1], m.triangles[h]);
    }
}

TEST(Adjacency, SameDirectionSharedEdgeIsInconsistent) {
    // Both triangles run 0 -> 1.
    const std::vector<std::uint32_t> tri = {0, 1, 2, 0, 1, 3};
    const Adjacency adj = build_adjacency(tri, 4);
    EXPECT_EQ(adj.edge_kinds[0], EdgeKind::inconsistent);
    EXPECT_EQ(adj.edge_kinds[3], EdgeKind::inconsistent);
    EXPECT_EQ(adj.adjacency[1], 0u);
    EXPECT_EQ(adj.adjacency[7], 0u);
    EXPECT_EQ(adj.inconsistent_edges, 1u);
    EXPECT_EQ(adj.boundary_edges, 4u);
}

TEST(Adjacency, FlippedBoxFaceGivesFourInconsistentEdges) {
    TriMesh cube = box({1.0f, 1.0f, 1.0f});
    std::swap(cube.indices[1], cube.indices[2]);  // the first face's two triangles
    std::swap(cube.indices[4], cube.indices[5]);
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(cube, &report);
    EXPECT_EQ(report.inconsistent_edges, 4u);
    EXPECT_EQ(count_kind(m.edge_kinds, EdgeKind::inconsistent), 8u);
    EXPECT_EQ(report.boundary_edges, 0u);
}

TEST(Adjacency, MatchesReferenceOnPrimitives) {
    for (const TriMesh& mesh :
         {box({1, 1, 1}), open_box({1, 2, 3}), uv_sphere(1.0f, 7, 9), grid(9, 7, 0.5f, 4),
          pyramid(1.0f, 2.0f), cylinder(1, 1, 11), fin()}) {
        const AdjacencyMesh welded = build_line_mesh(mesh);
        expect_matches_reference(welded.triangles, welded.positions.size());
        // Unwelded, every split seam is a boundary; the builder must agree there too.
        expect_matches_reference(mesh.indices, mesh.positions.size());
    }
}

TEST(Adjacency, MatchesReferenceOnRandomTriangleSoup) {
    // Few vertices and many triangles: lots of non-manifold, inconsistent and repeated edges.
    Rng rng(1234);
    for (int round = 0; round < 20; ++round) {
        const std::uint32_t vertices = 4 + rng.below(12);
        std::vector<std::uint32_t> tri;
        for (int i = 0; i < 60; ++i) {
            std::uint32_t a = rng.below(vertices), b = rng.below(vertices), c = rng.below(vertices);
            if (a == b || b == c || a == c) continue;
            tri.insert(tri.end(), {a, b, c});
        }
        expect_matches_reference(tri, vertices);
    }
}

TEST(Adjacency, HighValenceFanMatchesReference) {
    // Vertex 0 is on 5000 triangles: its edge bucket takes the sorting path.
    std::vector<std::uint32_t> tri;
    const std::uint32_t rim = 5000;
    for (std::uint32_t i = 0; i < rim; ++i) tri.insert(tri.end(), {0, 1 + i, 1 + (i + 1) % rim});
    expect_matches_reference(tri, rim + 1);
    const Adjacency adj = build_adjacency(tri, rim + 1);
    EXPECT_EQ(adj.boundary_edges, rim);
    EXPECT_FALSE(adj.maybe_coincident_faces);
}

TEST(Adjacency, SameInputGivesIdenticalOutput) {
    const AdjacencyMesh welded = build_line_mesh(uv_sphere(2.0f, 30, 40));
    const Adjacency a = build_adjacency(welded.triangles, welded.positions.size());
    const Adjacency b = build_adjacency(welded.triangles, welded.positions.size());
    EXPECT_EQ(a.adjacency, b.adjacency);
    EXPECT_EQ(a.edge_kinds, b.edge_kinds);
}

TEST(Adjacency, FlagsPossibleCoincidentFacesOnlyWhenPresent) {
    const AdjacencyMesh cube = build_line_mesh(box({1, 1, 1}));
    EXPECT_FALSE(build_adjacency(cube.triangles, cube.positions.size()).maybe_coincident_faces);
    std::vector<std::uint32_t> twin = {0, 1, 2, 0, 2, 1};
    EXPECT_TRUE(build_adjacency(twin, 3).maybe_coincident_faces);
}

TEST(Adjacency, RejectsBadInput) {
    const std::vector<std::uint32_t> out_of_range = {0, 1, 5};
    EXPECT_THROW(build_adjacency(out_of_range, 3), std::invalid_argument);
    const std::vector<std::uint32_t> ragged = {0, 1};
    EXPECT_THROW(build_adjacency(ragged, 3), std::invalid_argument);
    EXPECT_TRUE(build_adjacency({}, 0).adjacency.empty());
}

}  // namespace
}  // namespace bz::geo
