#include "geometry/line_mesh/line_mesh.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "geometry/generated/primitives.h"
#include "reference_adjacency.h"

namespace bz::geo {
namespace {

using test::count_kind;

void expect_same(const AdjacencyMesh& a, const AdjacencyMesh& b) {
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.adjacency, b.adjacency);
    EXPECT_EQ(a.edge_kinds, b.edge_kinds);
}

glm::vec3 face_normal(const AdjacencyMesh& m, std::size_t t) {
    const glm::vec3 a = m.positions[m.triangles[3 * t]];
    return glm::cross(m.positions[m.triangles[3 * t + 1]] - a,
                      m.positions[m.triangles[3 * t + 2]] - a);
}

glm::vec3 face_centre(const AdjacencyMesh& m, std::size_t t) {
    return (m.positions[m.triangles[3 * t]] + m.positions[m.triangles[3 * t + 1]] +
            m.positions[m.triangles[3 * t + 2]]) /
           3.0f;
}

// For a convex mesh around the origin: every face points away from it.
void expect_outward(const AdjacencyMesh& m) {
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        EXPECT_GT(glm::dot(face_normal(m, t), face_centre(m, t)), 0.0f) << "triangle " << t;
    }
}

TEST(LineMesh, SphereSeamsAndPolesWeldIntoAClosedSurface) {
    const std::uint32_t rings = 12, segments = 20;
    const TriMesh sphere = uv_sphere(1.5f, rings, segments);
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(sphere, &report);
    EXPECT_EQ(report.input_triangles, 2u * segments * (rings - 1));
    EXPECT_EQ(m.triangle_count(), report.input_triangles);
    EXPECT_EQ(report.welded_vertices, 2u + (rings - 1) * segments);
    EXPECT_EQ(m.positions.size(), report.welded_vertices);
    EXPECT_EQ(report.boundary_edges, 0u);
    EXPECT_EQ(count_kind(m.edge_kinds, EdgeKind::interior), m.edge_kinds.size());
    // Unwelded, the seam column would be open: the weld is what closes it.
    const test::ReferenceAdjacency raw = test::reference_adjacency(sphere.indices);
    EXPECT_GT(count_kind(raw.kinds, EdgeKind::boundary), 0u);
}

TEST(LineMesh, TiledGridSeamsWeldSoOnlyTheRimIsBoundary) {
    const std::uint32_t nx = 13, nz = 9;
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(grid(nx, nz, 0.25f, 4), &report);
    EXPECT_EQ(report.welded_vertices, (nx + 1u) * (nz + 1u));
    EXPECT_EQ(report.boundary_edges, 2u * (nx + nz));
    EXPECT_EQ(count_kind(m.edge_kinds, EdgeKind::boundary), 2u * (nx + nz));
    EXPECT_EQ(count_kind(m.edge_kinds, EdgeKind::interior), m.edge_kinds.size() - 2u * (nx + nz));
}

TEST(LineMesh, MillionTriangleGridHasOnlyTheOuterRimAsBoundary) {
    const std::uint32_t n = 708;  // 2 * 708^2 = 1,002,528 triangles
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(grid(n, n, 1.0f, 16), &report);
    ASSERT_EQ(m.triangle_count(), 2u * n * n);
    EXPECT_GE(m.triangle_count(), 1'000'000u);
    EXPECT_EQ(report.welded_vertices, (n + 1u) * (n + 1u));
    EXPECT_EQ(report.boundary_edges, 4u * n);
    EXPECT_EQ(report.non_manifold_edges + report.inconsistent_edges, 0u);
    std::size_t boundary = 0;
    const float rim = 0.5f * static_cast<float>(n);
    for (std::size_t h = 0; h < m.edge_kinds.size(); ++h) {
        if (m.edge_kinds[h] != EdgeKind::boundary) continue;
        ++boundary;
        const glm::vec3 p = m.positions[m.triangles[h]];
        EXPECT_TRUE(std::abs(p.x) == rim || std::abs(p.z) == rim);
    }
    EXPECT_EQ(boundary, 4u * n);
}

TEST(LineMesh, NegativeZeroWeldsWithPositiveZero) {
    TriMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, 0, -0.0f}, {0, -1, 0}, {1, 0, 0}};
    // The second triangle runs the first one's edge 0 -> 1 backwards, through copies of its
    // corners, one of them written with negative zeros.
    m.indices = {0, 1, 2, 3, 4, 5};
    MeshReport report;
    const AdjacencyMesh out = build_line_mesh(m, &report);
    EXPECT_EQ(report.welded_vertices, 4u);
    EXPECT_EQ(count_kind(out.edge_kinds, EdgeKind::interior), 2u);
}

TEST(LineMesh, TwinFacesAreRemovedAndTheResultEqualsTheSingleSidedMesh) {
    for (const TriMesh& single : {box({1, 2, 3}), uv_sphere(1.0f, 8, 10), grid(6, 5, 1.0f, 2)}) {
        MeshReport report;
        const AdjacencyMesh twinned = build_line_mesh(twin_faced(single), &report);
        EXPECT_EQ(report.twins_removed, single.triangle_count());
        EXPECT_EQ(report.input_triangles, 2 * single.triangle_count());
        EXPECT_EQ(report.duplicates_removed, 0u);
        expect_same(twinned, build_line_mesh(single));
    }
}

TEST(LineMesh, TwinKeepsTheFaceThatAgreesWithItsNeighbours) {
    // Only one face of the box is doubled, and the inward copy comes first in the file.
    const TriMesh cube = box({1, 1, 1});
    TriMesh m = cube;
    m.indices.clear();
    m.indices.insert(m.indices.end(), {cube.indices[0], cube.indices[2], cube.indices[1]});
    m.indices.insert(m.indices.end(), cube.indices.begin(), cube.indices.end());
    MeshReport report;
    const AdjacencyMesh out = build_line_mesh(m, &report);
    EXPECT_EQ(report.twins_removed, 1u);
    ASSERT_EQ(out.triangle_count(), 12u);
    EXPECT_EQ(report.inconsistent_edges + report.non_manifold_edges + report.boundary_edges, 0u);
    expect_outward(out);
}

TEST(LineMesh, FullyTwinnedMeshInAnyOrderComesOutConsistentlyWound) {
    // Outward and inward copies interleaved, inward first for every other face: the first
    // pair decides (keep the first face), and its winding spreads to the rest.
    const TriMesh cube = box({1, 1, 1});
    TriMesh m = cube;
    m.indices.clear();
    for (std::size_t t = 0; t < cube.triangle_count(); ++t) {
        const std::uint32_t a = cube.indices[3 * t], b = cube.indices[3 * t + 1],
                            c = cube.indices[3 * t + 2];
        if (t % 2 == 0)
            m.indices.insert(m.indices.end(), {a, c, b, a, b, c});
        else
            m.indices.insert(m.indices.end(), {a, b, c, a, c, b});
    }
    MeshReport report;
    const AdjacencyMesh out = build_line_mesh(m, &report);
    EXPECT_EQ(report.twins_removed, 12u);
    ASSERT_EQ(out.triangle_count(), 12u);
    EXPECT_EQ(report.inconsistent_edges + report.non_manifold_edges + report.boundary_edges, 0u);
    // The very first face is an inward copy, so the whole result is inward.
    for (std::size_t t = 0; t < out.triangle_count(); ++t) {
        EXPECT_LT(glm::dot(face_normal(out, t), face_centre(out, t)), 0.0f);
    }
}

TEST(LineMesh, ExactDuplicatesAreRemovedKeepingTheFirst) {
    const TriMesh cube = box({1, 1, 1});
    TriMesh m = cube;
    m.indices.insert(m.indices.end(), cube.indices.begin(), cube.indices.begin() + 9);
    MeshReport report;
    const AdjacencyMesh out = build_line_mesh(m, &report);
    EXPECT_EQ(report.duplicates_removed, 3u);
    EXPECT_EQ(report.twins_removed, 0u);
    expect_same(out, build_line_mesh(cube));
}

TEST(LineMesh, DegenerateTrianglesAreDropped) {
    const TriMesh cube = box({1, 1, 1});
    TriMesh m = cube;
    const auto n = static_cast<std::uint32_t>(m.positions.size());
    // Collinear on fresh vertices (which must not survive as unused vertices), a repeated
    // vertex, and a triangle whose corners weld into one point.
    m.positions.insert(m.positions.end(), {{5, 5, 5}, {6, 6, 6}, {7, 7, 7}});
    m.indices.insert(m.indices.end(), {n, n + 1, n + 2, 0, 0, 1});
    m.positions.push_back(m.positions[0]);
    m.indices.insert(m.indices.end(), {0, n + 3, 1});
    MeshReport report;
    const AdjacencyMesh out = build_line_mesh(m, &report);
    EXPECT_EQ(report.degenerate_removed, 3u);
    EXPECT_EQ(report.input_triangles, 15u);
    expect_same(out, build_line_mesh(cube));
}

TEST(LineMesh, SameInputTwiceGivesIdenticalOutput) {
    TriMesh m = twin_faced(uv_sphere(1.0f, 16, 24));
    const TriMesh extra = fin();
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), extra.positions.begin(), extra.positions.end());
    for (std::uint32_t i : extra.indices) m.indices.push_back(base + i);
    MeshReport r1, r2;
    const AdjacencyMesh a = build_line_mesh(m, &r1);
    const AdjacencyMesh b = build_line_mesh(m, &r2);
    expect_same(a, b);
    EXPECT_EQ(r1.twins_removed, r2.twins_removed);
    EXPECT_EQ(r1.non_manifold_edges, 1u);
}

TEST(LineMesh, OutputMatchesTheReferenceAdjacencyOfItsOwnTriangles) {
    const AdjacencyMesh m = build_line_mesh(twin_faced(cylinder(1.0f, 2.0f, 16)));
    const test::ReferenceAdjacency ref = test::reference_adjacency(m.triangles);
    EXPECT_EQ(m.adjacency, ref.adjacency);
    EXPECT_EQ(m.edge_kinds, ref.kinds);
}

TEST(LineMesh, RejectsOutOfRangeIndices) {
    TriMesh m = box({1, 1, 1});
    m.indices.back() = 1000;
    EXPECT_THROW(build_line_mesh(m), std::invalid_argument);
    m.indices.pop_back();
    EXPECT_THROW(build_line_mesh(m), std::invalid_argument);
}

TEST(LineMesh, EmptyMeshGivesEmptyOutput) {
    MeshReport report;
    const AdjacencyMesh m = build_line_mesh(TriMesh{}, &report);
    EXPECT_EQ(m.triangle_count(), 0u);
    EXPECT_EQ(report.welded_vertices, 0u);
}

}  // namespace
}  // namespace bz::geo
