#include "geometry/derived/edge_clusters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "geometry/derived/meshlets.h"

namespace bz::geo {

namespace {

// Meshlets of at most this many triangles: about 1.5 edges per triangle keeps most meshlets'
// edges within one cluster (kMaxClusterEdges). meshoptimizer wants a multiple of 4.
constexpr std::size_t kMeshletTriangles = 40;
constexpr std::size_t kMeshletVertices = 64;

// A triangle by its vertices, rotated so the smallest comes first (winding kept): the same key
// for a triangle and its copy in a meshlet.
using TriangleKey = std::array<std::uint32_t, 3>;
TriangleKey triangle_key(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (b < a && b <= c) return {b, c, a};
    if (c < a && c < b) return {c, a, b};
    return {a, b, c};
}

// The meshlet of every triangle (kNoVertex for a triangle no meshlet holds).
std::vector<std::uint32_t> meshlet_of_triangles(const AdjacencyMesh& mesh) {
    const std::size_t tris = mesh.triangle_count();
    std::vector<std::uint32_t> out(tris, kNoVertex);
    if (tris == 0) return out;
    const Meshlets built =
        build_meshlets(mesh, kMeshletVertices, kMeshletTriangles, kMeshletConeWeight);
    // Match the meshlets' triangles to the mesh's by their vertices: both lists sorted by key
    // (then by index, so repeated triangles pair off in order).
    std::vector<std::pair<TriangleKey, std::uint32_t>> original(tris), placed;
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        original[t] = {triangle_key(v[0], v[1], v[2]), static_cast<std::uint32_t>(t)};
    }
    placed.reserve(tris);
    for (std::size_t m = 0; m < built.meshlets.size(); ++m) {
        const meshopt_Meshlet& ml = built.meshlets[m];
        for (std::size_t t = 0; t < ml.triangle_count; ++t) {
            placed.push_back({triangle_key(built.vertex(ml, t, 0), built.vertex(ml, t, 1),
                                           built.vertex(ml, t, 2)),
                              static_cast<std::uint32_t>(m)});
        }
    }
    std::sort(original.begin(), original.end());
    std::sort(placed.begin(), placed.end());
    std::size_t j = 0;
    for (const auto& [key, t] : original) {
        while (j < placed.size() && placed[j].first < key) ++j;
        if (j < placed.size() && placed[j].first == key) out[t] = placed[j++].second;
    }
    return out;
}

float crease_key(const MeshEdge& e) {
    if (e.face_b == kNoVertex || e.opp_b == kNoVertex) return kAlwaysFeatureKey;
    if (e.flags & kEdgeMaterialBoundary) return kMaterialKey;
    if (std::isnan(e.cos_dihedral)) return 2.0f;
    return e.cos_dihedral >= 1.0f ? kFlatKey : e.cos_dihedral;
}

// A cluster of edges [first, first + count) of `c.edges`, its bounds around the candidates
// (the edges before the first flat one) and the faces on both sides of each.
EdgeCluster bound_cluster(const AdjacencyMesh& mesh,
                          const std::vector<std::optional<glm::dvec3>>& face_normals,
                          const ClusteredEdges& c, std::uint32_t first, std::uint32_t all) {
    std::uint32_t count = 0;
    while (count < all && c.crease_keys[first + count] < kFlatKey) ++count;
    std::vector<std::uint32_t> vertices;
    std::vector<std::optional<glm::dvec3>> normals;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const MeshEdge& e = c.edges[i];
        vertices.insert(vertices.end(), {e.a, e.b});
        for (const std::uint32_t f : {e.face_a, e.face_b})
            if (f != kNoVertex) normals.push_back(face_normals[f]);
    }
    EdgeCluster out{bound_faces(mesh, vertices, normals)};
    out.first = first;
    out.count = all;
    out.candidates = count;
    return out;
}

}  // namespace

ClusteredEdges cluster_edges(const AdjacencyMesh& mesh, std::span<const MeshEdge> edges) {
    ClusteredEdges out;
    const std::vector<std::uint32_t> meshlet = meshlet_of_triangles(mesh);
    const std::uint32_t meshlets =
        meshlet.empty()
            ? 0u
            : 1u + *std::max_element(
                       meshlet.begin(), meshlet.end(), [](std::uint32_t a, std::uint32_t b) {
                           return (a == kNoVertex ? 0u : a) < (b == kNoVertex ? 0u : b);
                       });
    // Edges of triangles no meshlet holds go to one last group.
    const auto group_of = [&](const MeshEdge& e) {
        const std::uint32_t m = e.face_a < meshlet.size() ? meshlet[e.face_a] : kNoVertex;
        return m == kNoVertex ? meshlets : m;
    };
    std::vector<std::uint32_t> start(meshlets + 2, 0);
    for (const MeshEdge& e : edges) ++start[group_of(e) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> order(edges.size());
    {
        std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
        for (std::uint32_t i = 0; i < edges.size(); ++i) order[next[group_of(edges[i])]++] = i;
    }
    out.edges.reserve(edges.size());
    out.crease_keys.reserve(edges.size());

    const std::vector<std::optional<glm::dvec3>> normals = unit_face_normals(mesh);

    for (std::uint32_t g = 0; g + 1 < start.size(); ++g) {
        const std::uint32_t begin = start[g], end = start[g + 1];
        if (begin == end) continue;
        std::vector<std::uint32_t> group(order.begin() + begin, order.begin() + end);
        std::sort(group.begin(), group.end(), [&](std::uint32_t x, std::uint32_t y) {
            const float kx = crease_key(edges[x]), ky = crease_key(edges[y]);
            return kx != ky ? kx < ky : x < y;
        });
        // Evenly sized clusters of at most kMaxClusterEdges, each sorted by crease key.
        const std::uint32_t n = end - begin;
        const std::uint32_t pieces = (n + kMaxClusterEdges - 1) / kMaxClusterEdges;
        for (std::uint32_t p = 0; p < pieces; ++p) {
            const std::uint32_t from = n * p / pieces, to = n * (p + 1) / pieces;
            const auto first = static_cast<std::uint32_t>(out.edges.size());
            for (std::uint32_t i = from; i < to; ++i) {
                out.edges.push_back(edges[group[i]]);
                out.crease_keys.push_back(crease_key(edges[group[i]]));
            }
            out.clusters.push_back(bound_cluster(mesh, normals, out, first, to - from));
        }
    }
    for (std::size_t first = 0; first < out.clusters.size(); first += kClustersPerGroup) {
        const std::size_t end = std::min(out.clusters.size(), first + kClustersPerGroup);
        std::vector<std::uint32_t> vertices;
        std::vector<std::optional<glm::dvec3>> group_normals;
        EdgeClusterGroup group;
        for (std::size_t c = first; c < end; ++c) {
            const EdgeCluster& k = out.clusters[c];
            for (std::uint32_t i = k.first; i < k.first + k.candidates; ++i) {
                const MeshEdge& e = out.edges[i];
                vertices.insert(vertices.end(), {e.a, e.b});
                for (const std::uint32_t f : {e.face_a, e.face_b})
                    if (f != kNoVertex) group_normals.push_back(normals[f]);
                group.min_key = std::min(group.min_key, out.crease_keys[i]);
            }
        }
        static_cast<ClusterBounds&>(group) = bound_faces(mesh, vertices, group_normals);
        out.groups.push_back(group);
    }
    std::vector<std::uint32_t> candidates;
    for (const EdgeCluster& k : out.clusters) {
        for (std::uint32_t i = k.first; i < k.first + k.candidates; ++i)
            candidates.insert(candidates.end(), {out.edges[i].a, out.edges[i].b});
    }
    out.all = bound_faces(mesh, candidates, {});
    return out;
}

std::uint32_t crease_prefix(const ClusteredEdges& c, const EdgeCluster& cluster, float cos_crease) {
    const auto begin = c.crease_keys.begin() + cluster.first;
    return static_cast<std::uint32_t>(std::lower_bound(begin, begin + cluster.count, cos_crease) -
                                      begin);
}

}  // namespace bz::geo
