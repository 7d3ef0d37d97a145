// Edge clusters (geometry/derived/edge_clusters.h): every edge in exactly one cluster, clusters
// within their size, crease candidates first, and bounds that hold what they claim.
#include "geometry/derived/edge_clusters.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

void expect_well_formed(const AdjacencyMesh& m) {
    const std::vector<MeshEdge> list = build_edge_list(m);
    const ClusteredEdges c = cluster_edges(m, list);
    ASSERT_EQ(c.edges.size(), list.size());
    ASSERT_EQ(c.crease_keys.size(), list.size());
    std::set<std::uint32_t> ids;
    for (const MeshEdge& e : c.edges) ids.insert(e.id);
    EXPECT_EQ(ids.size(), list.size()) << "an edge is missing or repeated";
    std::uint32_t next = 0;
    for (const EdgeCluster& k : c.clusters) {
        EXPECT_EQ(k.first, next) << "clusters must tile the list in order";
        EXPECT_GT(k.count, 0u);
        EXPECT_LE(k.count, kMaxClusterEdges);
        next = k.first + k.count;
        EXPECT_TRUE(std::is_sorted(c.crease_keys.begin() + k.first,
                                   c.crease_keys.begin() + k.first + k.count));
        EXPECT_LE(k.candidates, k.count);
        for (std::uint32_t i = k.first; i < k.first + k.count; ++i)
            EXPECT_EQ(i < k.first + k.candidates, c.crease_keys[i] < kFlatKey);
        for (std::uint32_t i = k.first; i < k.first + k.candidates; ++i) {
            const MeshEdge& e = c.edges[i];
            // The sphere holds both end points.
            for (const std::uint32_t v : {e.a, e.b})
                EXPECT_LE(glm::length(m.positions[v] - k.center), k.radius * (1.0f + 1e-5f));
            // The cone holds both faces' normals.
            if (k.cos_spread > 0.0f) {
                for (const std::uint32_t f : {e.face_a, e.face_b}) {
                    if (f == kNoVertex) continue;
                    const std::uint32_t* t = &m.triangles[3 * f];
                    const glm::vec3 n =
                        glm::normalize(glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                                  m.positions[t[2]] - m.positions[t[0]]));
                    EXPECT_GE(glm::dot(n, k.axis), k.cos_spread - 1e-6f);
                }
            }
        }
    }
    EXPECT_EQ(next, list.size());
}

TEST(EdgeClusters, TileTheListWithinSizeOnASphereABoxAndAnOpenMesh) {
    expect_well_formed(build_line_mesh(uv_sphere(1.0f, 40, 80)));
    expect_well_formed(build_line_mesh(box(glm::vec3(1.0f, 2.0f, 3.0f))));
    expect_well_formed(build_line_mesh(open_box(glm::vec3(1.0f))));
    expect_well_formed(build_line_mesh(fin()));
    expect_well_formed(build_line_mesh(grid(30, 30, 10.0f, 1)));
}

TEST(EdgeClusters, FaceBIsTheTriangleThatWalksTheEdgeBackwards) {
    const AdjacencyMesh m = build_line_mesh(uv_sphere(1.0f, 12, 24));
    for (const MeshEdge& e : build_edge_list(m)) {
        ASSERT_NE(e.face_b, kNoVertex);
        const std::uint32_t* t = &m.triangles[3 * e.face_b];
        bool walks_back = false;
        for (int i = 0; i < 3; ++i) walks_back |= t[i] == e.b && t[(i + 1) % 3] == e.a;
        EXPECT_TRUE(walks_back);
        const std::uint32_t* ta = &m.triangles[3 * e.face_a];
        EXPECT_TRUE(std::count(ta, ta + 3, e.opp_a) == 1);
    }
}

TEST(EdgeClusters, BoundaryEdgesComeFirstAndCreasesFollowTheThreshold) {
    const AdjacencyMesh m = build_line_mesh(open_box(glm::vec3(1.0f)));
    const ClusteredEdges c = cluster_edges(m, build_edge_list(m));
    std::size_t boundary = 0, creases = 0;
    for (const EdgeCluster& k : c.clusters) {
        // Prefix at a threshold below every crease (-2: no creases): only the boundary edges.
        const std::uint32_t always = crease_prefix(c, k, -2.0f);
        for (std::uint32_t i = k.first; i < k.first + k.count; ++i)
            EXPECT_EQ(i < k.first + always, c.edges[i].opp_b == kNoVertex);
        boundary += always;
        // At cos 0.5 (60 degrees) the box's 90 degree edges are creases too.
        creases += crease_prefix(c, k, 0.5f) - always;
    }
    EXPECT_EQ(boundary, 4u);
    EXPECT_EQ(creases, 8u);  // 12 box edges less the open top's 4
}

}  // namespace
}  // namespace bz::geo
