// The unique edge list of the compute line method (geometry/derived/edge_list.h).
#include "geometry/derived/edge_list.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

// Every triangle edge, as (from, to) in its triangle's winding.
std::multiset<std::pair<std::uint32_t, std::uint32_t>> half_edges(const AdjacencyMesh& m) {
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> out;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        for (int e = 0; e < 3; ++e)
            out.insert({m.triangles[3 * t + e], m.triangles[3 * t + (e + 1) % 3]});
    }
    return out;
}

TEST(EdgeList, ClosedBoxHasEachEdgeOnceLowToHigh) {
    const AdjacencyMesh m = build_line_mesh(box(glm::vec3(1.0f)));
    const std::vector<MeshEdge> edges = build_edge_list(m);
    ASSERT_EQ(edges.size(), 18u);  // 12 box edges + 6 face diagonals
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    const auto halves = half_edges(m);
    int sharp = 0;
    for (const MeshEdge& e : edges) {
        EXPECT_LT(e.a, e.b);
        EXPECT_EQ(e.flags, kEdgeInterior);
        EXPECT_NE(e.opp_b, kNoVertex);
        EXPECT_TRUE(seen.insert({e.a, e.b}).second) << "edge listed twice";
        // Face A walks a -> b, face B walks b -> a.
        EXPECT_EQ(halves.count({e.a, e.b}), 1u);
        EXPECT_EQ(halves.count({e.b, e.a}), 1u);
        if (e.cos_dihedral < 0.5f) {
            ++sharp;
            EXPECT_NEAR(e.cos_dihedral, 0.0f, 1e-6f);  // the box's 90 degree edges
        } else {
            EXPECT_NEAR(e.cos_dihedral, 1.0f, 1e-6f);  // flat diagonals
        }
    }
    EXPECT_EQ(sharp, 12);
}

TEST(EdgeList, OpenBoxBoundaryEdgesHaveNoSecondFace) {
    const AdjacencyMesh m = build_line_mesh(open_box(glm::vec3(1.0f)));
    const std::vector<MeshEdge> edges = build_edge_list(m);
    int boundary = 0;
    for (const MeshEdge& e : edges) {
        if (e.flags == kEdgeBoundary) {
            ++boundary;
            EXPECT_EQ(e.opp_b, kNoVertex);
            EXPECT_EQ(e.cos_dihedral, 2.0f);
        }
    }
    EXPECT_EQ(boundary, 4);  // the open top's rim
}

TEST(EdgeList, NonManifoldEdgeIsListedOncePerFace) {
    // fin(): three faces on one edge. The geometry shader emits that edge once per face.
    const AdjacencyMesh m = build_line_mesh(fin());
    const std::vector<MeshEdge> edges = build_edge_list(m);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> per_edge;
    for (const MeshEdge& e : edges) {
        if (e.flags == kEdgeNonManifold) ++per_edge[{std::min(e.a, e.b), std::max(e.a, e.b)}];
    }
    ASSERT_EQ(per_edge.size(), 1u);
    EXPECT_EQ(per_edge.begin()->second, 3);
}

TEST(EdgeList, CountMatchesEulerOnASphere) {
    const AdjacencyMesh m = build_line_mesh(uv_sphere(1.0f, 12, 24));
    // Closed, every edge interior: E = 3F / 2.
    EXPECT_EQ(build_edge_list(m).size() * 2, m.triangle_count() * 3);
}

TEST(VertexNormals, PointOutwardOnASphere) {
    const AdjacencyMesh m = build_line_mesh(uv_sphere(1.0f, 12, 24));
    const std::vector<glm::vec3> n = vertex_normals(m);
    ASSERT_EQ(n.size(), m.positions.size());
    for (std::size_t i = 0; i < n.size(); ++i) {
        EXPECT_NEAR(glm::length(n[i]), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(n[i], glm::normalize(m.positions[i])), 0.95f) << "vertex " << i;
    }
}

}  // namespace
}  // namespace bz::geo
