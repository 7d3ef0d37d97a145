#include "geometry/derived/triangle_clusters.h"

#include "geometry/derived/closure.h"
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
    if (mesh.triangle_count() == 0 || mesh.positions.empty()) return one_cluster(mesh);
    return cluster_triangles(mesh, connected_pieces(mesh));
}

ClusteredTriangles cluster_triangles(const AdjacencyMesh& mesh, const Pieces& pieces) {
    const std::size_t tris = mesh.triangle_count();
    if (tris == 0 || mesh.positions.empty()) return one_cluster(mesh);
    // The triangles of outward-closed pieces and the rest go to meshlets of their own, so a
    // cluster of closed pieces can skip its back faces (TriangleCluster::closed).
    std::vector<std::uint32_t> closed_indices, open_indices;
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        const bool closed = pieces.pieces[pieces.piece_of_vertex[v[0]]].outward_closed;
        (closed ? closed_indices : open_indices)
            .insert((closed ? closed_indices : open_indices).end(), v, v + 3);
    }
    const Meshlets built[2] = {build_meshlets(mesh, closed_indices, kClusterVertices,
                                              kClusterTriangles, kMeshletConeWeight),
                               build_meshlets(mesh, open_indices, kClusterVertices,
                                              kClusterTriangles, kMeshletConeWeight)};
    std::size_t placed = 0;
    for (const Meshlets& b : built)
        for (const meshopt_Meshlet& ml : b.meshlets) placed += ml.triangle_count;
    if (placed != tris) return one_cluster(mesh);

    // A meshlet keeps each triangle's vertices and winding, so its normal is the original's.
    ClusteredTriangles out;
    out.indices.reserve(mesh.triangles.size());
    out.clusters.reserve(built[0].meshlets.size() + built[1].meshlets.size());
    std::vector<std::uint32_t> cluster_vertices;
    std::vector<std::optional<glm::dvec3>> cluster_normals;
    for (const Meshlets& b : built) {
        for (const meshopt_Meshlet& ml : b.meshlets) {
            const auto first = static_cast<std::uint32_t>(out.indices.size());
            cluster_vertices.assign(b.vertices.begin() + ml.vertex_offset,
                                    b.vertices.begin() + ml.vertex_offset + ml.vertex_count);
            cluster_normals.clear();
            const auto first_vertex = static_cast<std::uint32_t>(out.vertices.size());
            out.vertices.insert(out.vertices.end(), cluster_vertices.begin(),
                                cluster_vertices.end());
            for (std::size_t t = 0; t < ml.triangle_count; ++t) {
                const std::uint32_t a = b.vertex(ml, t, 0), c1 = b.vertex(ml, t, 1),
                                    c2 = b.vertex(ml, t, 2);
                out.indices.insert(out.indices.end(), {a, c1, c2});
                const unsigned char* local = &b.local[ml.triangle_offset + 3 * t];
                out.corners.push_back(std::uint32_t(local[0]) | std::uint32_t(local[1]) << 8 |
                                      std::uint32_t(local[2]) << 16);
                cluster_normals.push_back(unit_normal(mesh, a, c1, c2));
            }
            TriangleCluster k{bound_faces(mesh, cluster_vertices, cluster_normals)};
            k.closed = &b == &built[0];
            k.closed_box = {glm::vec3(INFINITY), glm::vec3(-INFINITY)};
            for (const std::uint32_t v : cluster_vertices) {
                const Bounds& box = pieces.pieces[pieces.piece_of_vertex[v]].box;
                k.closed_box.min = glm::min(k.closed_box.min, box.min);
                k.closed_box.max = glm::max(k.closed_box.max, box.max);
            }
            k.first_index = first;
            k.index_count = static_cast<std::uint32_t>(out.indices.size()) - first;
            k.first_vertex = first_vertex;
            k.vertex_count = ml.vertex_count;
            out.clusters.push_back(k);
        }
    }
    out.all = bound_faces(mesh, out.indices, {});
    return out;
}

}  // namespace bz::geo
