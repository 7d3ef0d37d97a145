// Triangle clusters (geometry/derived/triangle_clusters.h): every triangle once, with its
// winding, and bounds that hold every vertex and every face normal of the cluster.
#include "geometry/derived/triangle_clusters.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

using Triple = std::array<std::uint32_t, 3>;

// A triangle with its smallest vertex first, winding kept.
Triple rotated(const std::uint32_t* v) {
    const int m = v[0] <= v[1] && v[0] <= v[2] ? 0 : (v[1] <= v[2] ? 1 : 2);
    return {v[m], v[(m + 1) % 3], v[(m + 2) % 3]};
}

std::vector<Triple> sorted_triangles(const std::vector<std::uint32_t>& indices) {
    std::vector<Triple> out;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) out.push_back(rotated(&indices[i]));
    std::sort(out.begin(), out.end());
    return out;
}

void expect_sound(const AdjacencyMesh& mesh, const ClusteredTriangles& c) {
    EXPECT_EQ(sorted_triangles(c.indices), sorted_triangles(mesh.triangles));
    std::uint32_t next = 0;
    for (const TriangleCluster& k : c.clusters) {
        EXPECT_EQ(k.first_index, next);
        EXPECT_EQ(k.index_count % 3, 0u);
        EXPECT_GT(k.index_count, 0u);
        next += k.index_count;
        for (std::uint32_t i = k.first_index; i < k.first_index + k.index_count; ++i) {
            const glm::vec3 p = mesh.positions[c.indices[i]];
            EXPECT_LE(glm::length(p - k.center), k.radius) << "vertex outside the sphere";
        }
        // Its vertex list: distinct, within the limit, and each triangle's corners name its
        // own vertices in its own order (the compute prepass reads only these).
        if (k.vertex_count > 0) {
            EXPECT_LE(k.vertex_count, kClusterVertices);
            ASSERT_LE(k.first_vertex + k.vertex_count, c.vertices.size());
            std::vector<std::uint32_t> list(c.vertices.begin() + k.first_vertex,
                                            c.vertices.begin() + k.first_vertex + k.vertex_count);
            std::sort(list.begin(), list.end());
            EXPECT_EQ(std::adjacent_find(list.begin(), list.end()), list.end()) << "repeated";
            ASSERT_EQ(c.corners.size() * 3, c.indices.size());
            for (std::uint32_t i = k.first_index; i < k.first_index + k.index_count; ++i) {
                const std::uint32_t local = (c.corners[i / 3] >> (8 * (i % 3))) & 0xFFu;
                ASSERT_LT(local, k.vertex_count);
                EXPECT_EQ(c.vertices[k.first_vertex + local], c.indices[i]);
            }
        }
        if (!(k.cos_spread > 0.0f)) continue;
        for (std::uint32_t i = k.first_index; i < k.first_index + k.index_count; i += 3) {
            const auto n = unit_normal(mesh, c.indices[i], c.indices[i + 1], c.indices[i + 2]);
            ASSERT_TRUE(n.has_value());
            EXPECT_GE(glm::dot(glm::dvec3(k.axis), *n), static_cast<double>(k.cos_spread))
                << "normal outside the cone";
        }
    }
    EXPECT_EQ(next, c.indices.size());
}

TEST(TriangleClusters, ASphereSplitsIntoBoundedClustersWithTightCones) {
    const AdjacencyMesh mesh = build_line_mesh(uv_sphere(1.0f, 64, 128));
    const ClusteredTriangles c = cluster_triangles(mesh);
    expect_sound(mesh, c);
    for (const TriangleCluster& k : c.clusters) EXPECT_GT(k.vertex_count, 0u);
    EXPECT_GT(c.clusters.size(), mesh.triangle_count() / 124);
    std::size_t with_cone = 0;
    for (const TriangleCluster& k : c.clusters) with_cone += k.cos_spread > 0.5f;
    // A fine sphere's patches are nearly flat: almost every cluster has a narrow cone.
    EXPECT_GT(with_cone * 10, c.clusters.size() * 9);
}

TEST(TriangleClusters, AnOpenGridAndABoxAreSound) {
    expect_sound(build_line_mesh(grid(30, 20, 0.5f, 30)),
                 cluster_triangles(build_line_mesh(grid(30, 20, 0.5f, 30))));
    const AdjacencyMesh box_mesh = build_line_mesh(box(glm::vec3(1.0f, 2.0f, 3.0f)));
    expect_sound(box_mesh, cluster_triangles(box_mesh));
}

// Closed solids and an open sheet in one mesh: the solids' triangles and the sheet's go to
// clusters of their own, and only the solids' are closed, with a box that holds their pieces.
TEST(TriangleClusters, ClosedPiecesGetClustersOfTheirOwn) {
    TriMesh m = grid(40, 40, 0.25f, 40);  // 10 x 10, open
    const TriMesh ball = uv_sphere(0.5f, 16, 32);
    for (int i = 0; i < 9; ++i) {
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        const glm::vec3 at(float(i % 3) * 3.0f - 3.0f, 1.0f, float(i / 3) * 3.0f - 3.0f);
        for (const glm::vec3& p : ball.positions) m.positions.push_back(p + at);
        for (const std::uint32_t v : ball.indices) m.indices.push_back(base + v);
    }
    const AdjacencyMesh mesh = build_line_mesh(m);
    const ClusteredTriangles c = cluster_triangles(mesh);
    expect_sound(mesh, c);
    std::size_t closed = 0, open = 0;
    for (const TriangleCluster& k : c.clusters) {
        for (std::uint32_t i = k.first_index; i < k.first_index + k.index_count; ++i) {
            const glm::vec3 p = mesh.positions[c.indices[i]];
            // The sheet lies at y = 0, the balls at y >= 0.5.
            EXPECT_EQ(k.closed, p.y > 0.25f) << "a cluster mixes solids and the sheet";
            if (k.closed) {
                EXPECT_TRUE(glm::all(glm::lessThanEqual(k.closed_box.min, p)));
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(k.closed_box.max, p)));
            }
        }
        (k.closed ? closed : open) += k.index_count / 3;
    }
    EXPECT_EQ(closed, 9 * ball.triangle_count());
    EXPECT_EQ(open, 2u * 40 * 40);
}

TEST(TriangleClusters, AnEmptyMeshHasNoCluster) {
    EXPECT_TRUE(cluster_triangles(AdjacencyMesh{}).clusters.empty());
}

}  // namespace
}  // namespace bz::geo
