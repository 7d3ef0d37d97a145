// Material boundaries (geometry/line_mesh/material_edges.h): found once per mesh by
// build_line_mesh, carried through cleaning, handed to the edge list and its clusters.
#include "geometry/line_mesh/material_edges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <stdexcept>

#include "geometry/derived/edge_clusters.h"
#include "geometry/derived/edge_list.h"
#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

// An undirected edge by its end positions, lower end first (lexicographic).
std::pair<std::array<float, 3>, std::array<float, 3>> edge_of(const glm::vec3& a,
                                                              const glm::vec3& b) {
    std::array<float, 3> pa{a.x, a.y, a.z}, pb{b.x, b.y, b.z};
    if (pb < pa) std::swap(pa, pb);
    return {pa, pb};
}

using Edge = std::pair<std::array<float, 3>, std::array<float, 3>>;

// Every marked edge of the mesh, once each (an interior edge is marked from both its faces).
std::set<Edge> marked_edges(const AdjacencyMesh& m) {
    std::set<Edge> out;
    std::multiset<Edge> halves;
    for (std::size_t h = 0; h < m.material_edges.size(); ++h) {
        if (!m.material_edges[h]) continue;
        const std::size_t t = h / 3;
        const Edge e =
            edge_of(m.positions[m.triangles[h]], m.positions[m.triangles[t * 3 + (h + 1) % 3]]);
        out.insert(e);
        halves.insert(e);
    }
    for (const Edge& e : out) EXPECT_EQ(halves.count(e), 2u) << "marked from one side only";
    return out;
}

glm::vec3 normal_of(const TriMesh& m, std::size_t t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

// The unit cube whose top (+y) face has material 1 and every other face material 0.
TriMesh two_material_box() {
    TriMesh m = box(glm::vec3(1.0f));
    for (std::size_t t = 0; t < m.triangle_count(); ++t)
        m.face_materials.push_back(normal_of(m, t).y > 0.5f ? 1u : 0u);
    return m;
}

TEST(MaterialEdges, BoxWithATopOfAnotherMaterialMarksExactlyTheTopsFourEdges) {
    const AdjacencyMesh m = build_line_mesh(two_material_box());
    ASSERT_TRUE(m.has_material_edges());
    ASSERT_EQ(m.material_edges.size(), m.triangles.size());
    const std::set<Edge> got = marked_edges(m);
    const std::set<Edge> want = {edge_of({-1, 1, -1}, {1, 1, -1}), edge_of({1, 1, -1}, {1, 1, 1}),
                                 edge_of({1, 1, 1}, {-1, 1, 1}), edge_of({-1, 1, 1}, {-1, 1, -1})};
    EXPECT_EQ(got, want);  // not the top's diagonal, not the other eight box edges
}

TEST(MaterialEdges, OneMaterialOrNoneMarksNothing) {
    TriMesh m = box(glm::vec3(1.0f));
    EXPECT_FALSE(build_line_mesh(m).has_material_edges());
    m.face_materials.assign(m.triangle_count(), 7u);
    EXPECT_FALSE(build_line_mesh(m).has_material_edges());
}

// A flat 4x1 strip whose faces left of x = 0 have material 0 and the rest material 1.
TriMesh two_material_strip() {
    TriMesh m = grid(4, 1, 1.0f, 4);
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const glm::vec3 c = (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
                             m.positions[m.indices[3 * t + 2]]) /
                            3.0f;
        m.face_materials.push_back(c.x < 0.0f ? 0u : 1u);
    }
    return m;
}

TEST(MaterialEdges, CoplanarFacesOfTwoMaterialsMeetAtALine) {
    // A flat 4x1 strip split down the middle: no crease anywhere, one material line of two
    // grid edges at x = 0.
    const TriMesh m = two_material_strip();
    ASSERT_GT(m.triangle_count(), 0u);
    const AdjacencyMesh a = build_line_mesh(m);
    const std::set<Edge> got = marked_edges(a);
    ASSERT_FALSE(got.empty());
    for (const Edge& e : got) {
        EXPECT_FLOAT_EQ(e.first[0], 0.0f);
        EXPECT_FLOAT_EQ(e.second[0], 0.0f);
    }
}

TEST(MaterialEdges, CleaningKeepsEachFaceItsMaterial) {
    // A degenerate triangle and a duplicate face ahead of the box: dropped, and the box's
    // faces keep their own materials rather than shifting onto their neighbours'.
    TriMesh m = two_material_box();
    TriMesh dirty;
    dirty.positions = m.positions;
    dirty.indices = {0, 0, 1, m.indices[0], m.indices[1], m.indices[2]};
    dirty.face_materials = {5u, 9u};
    dirty.indices.insert(dirty.indices.end(), m.indices.begin(), m.indices.end());
    dirty.face_materials.insert(dirty.face_materials.end(), m.face_materials.begin(),
                                m.face_materials.end());
    MeshReport report;
    const AdjacencyMesh a = build_line_mesh(dirty, &report);
    EXPECT_EQ(report.degenerate_removed, 1u);
    EXPECT_EQ(report.duplicates_removed, 1u);
    EXPECT_EQ(a.triangle_count(), 12u);
    // The duplicate came first and kept material 9, so its face differs from its box
    // neighbours; everything else is as in the clean box.
    const AdjacencyMesh clean = build_line_mesh(two_material_box());
    std::set<Edge> want = marked_edges(clean);
    const std::set<Edge> got = marked_edges(a);
    EXPECT_TRUE(std::includes(got.begin(), got.end(), want.begin(), want.end()));
    EXPECT_GT(got.size(), want.size());
}

TEST(MaterialEdges, WrongMaterialCountIsRefused) {
    TriMesh m = box(glm::vec3(1.0f));
    m.face_materials = {0u, 1u};
    EXPECT_THROW(build_line_mesh(m), std::invalid_argument);
    const std::vector<std::uint32_t> tri = {0, 1, 2};
    const std::vector<EdgeKind> kinds(3, EdgeKind::boundary);
    const std::vector<std::uint32_t> two = {0u, 1u};
    EXPECT_THROW(find_material_edges(tri, kinds, two), std::invalid_argument);
}

TEST(MaterialEdges, EdgeListFlagsThemAndClustersAlwaysTestThem) {
    const TriMesh m = two_material_strip();
    const AdjacencyMesh a = build_line_mesh(m);
    const std::vector<MeshEdge> edges = build_edge_list(a);
    std::set<Edge> flagged;
    for (const MeshEdge& e : edges) {
        if (!(e.flags & kEdgeMaterialBoundary)) continue;
        EXPECT_EQ(e.flags & kEdgeKindMask, kEdgeInterior);
        flagged.insert(edge_of(a.positions[e.a], a.positions[e.b]));
    }
    EXPECT_EQ(flagged, marked_edges(a));
    // Coplanar edges are never tested (kFlatKey) - except material boundaries, which must be
    // in every cluster's crease prefix, whatever the threshold.
    const ClusteredEdges c = cluster_edges(a, edges);
    std::size_t in_prefix = 0;
    for (const EdgeCluster& k : c.clusters) {
        const std::uint32_t n = crease_prefix(c, k, 0.5f);
        for (std::uint32_t i = k.first; i < k.first + n; ++i)
            if (c.edges[i].flags & kEdgeMaterialBoundary) ++in_prefix;
    }
    EXPECT_EQ(in_prefix, flagged.size());
}

}  // namespace
}  // namespace bz::geo
