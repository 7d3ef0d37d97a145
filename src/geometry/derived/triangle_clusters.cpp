#include "geometry/derived/triangle_clusters.h"

#include "geometry/derived/meshlets.h"

namespace bz::geo {

namespace {

// Meshlets of at most this many vertices and triangles: large enough that a frame's draws stay
// few (one command per run of kept clusters), small enough that a silhouette's neighbourhood
// is a small share of them. meshoptimizer wants the triangle count a multiple of 4.
constexpr std::size_t kClusterTriangles = 124;

ClusteredTriangles one_cluster(const AdjacencyMesh& mesh) {
    ClusteredTriangles out;
    out.indices = mesh.triangles;
    const std::optional<glm::dvec3> no_cone[] = {std::nullopt};
    TriangleCluster all{bound_faces(mesh, mesh.triangles, no_cone)};
    out.all = all;
    all.index_count = static_cast<std::uint32_t>(mesh.triangles.size());
    if (all.index_count > 0) out.clusters.push_back(all);
    return out;
}

}  // namespace

ClusteredTriangles cluster_triangles(const AdjacencyMesh& mesh) {
    const std::size_t tris = mesh.triangle_count();
    if (tris == 0 || mesh.positions.empty()) return one_cluster(mesh);
    const Meshlets built =
        build_meshlets(mesh, kClusterVertices, kClusterTriangles, kMeshletConeWeight);
    std::size_t placed = 0;
    for (const meshopt_Meshlet& ml : built.meshlets) placed += ml.triangle_count;
    if (placed != tris) return one_cluster(mesh);

    // A meshlet keeps each triangle's vertices and winding, so its normal is the original's.
    ClusteredTriangles out;
    out.indices.reserve(mesh.triangles.size());
    out.clusters.reserve(built.meshlets.size());
    std::vector<std::uint32_t> cluster_vertices;
    std::vector<std::optional<glm::dvec3>> cluster_normals;
    for (const meshopt_Meshlet& ml : built.meshlets) {
        const auto first = static_cast<std::uint32_t>(out.indices.size());
        cluster_vertices.assign(built.vertices.begin() + ml.vertex_offset,
                                built.vertices.begin() + ml.vertex_offset + ml.vertex_count);
        cluster_normals.clear();
        const auto first_vertex = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.insert(out.vertices.end(), cluster_vertices.begin(), cluster_vertices.end());
        for (std::size_t t = 0; t < ml.triangle_count; ++t) {
            const std::uint32_t a = built.vertex(ml, t, 0), b = built.vertex(ml, t, 1),
                                c = built.vertex(ml, t, 2);
            out.indices.insert(out.indices.end(), {a, b, c});
            const unsigned char* local = &built.local[ml.triangle_offset + 3 * t];
            out.corners.push_back(std::uint32_t(local[0]) | std::uint32_t(local[1]) << 8 |
                                  std::uint32_t(local[2]) << 16);
            cluster_normals.push_back(unit_normal(mesh, a, b, c));
        }
        TriangleCluster k{bound_faces(mesh, cluster_vertices, cluster_normals)};
        k.first_index = first;
        k.index_count = static_cast<std::uint32_t>(out.indices.size()) - first;
        k.first_vertex = first_vertex;
        k.vertex_count = ml.vertex_count;
        out.clusters.push_back(k);
    }
    out.all = bound_faces(mesh, out.indices, {});
    return out;
}

}  // namespace bz::geo
