#include "geometry/derived/edge_clusters.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace bz::geo {

namespace {

// Meshlets of at most this many triangles: about 1.5 edges per triangle keeps most meshlets'
// edges within one cluster (kMaxClusterEdges). meshoptimizer wants a multiple of 4.
constexpr std::size_t kMeshletTriangles = 40;
constexpr std::size_t kMeshletVertices = 64;
// Weight meshoptimizer gives to tight normal cones against compact clusters.
constexpr float kConeWeight = 0.5f;
// The cone's half-angle is widened by this much of its cosine, for the rounding of the float
// normals the shader compares (the test also keeps a margin: render/lines/edge_culling.cpp).
constexpr double kConeSlack = 1e-5;

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
    const std::size_t bound =
        meshopt_buildMeshletsBound(mesh.triangles.size(), kMeshletVertices, kMeshletTriangles);
    std::vector<meshopt_Meshlet> meshlets(bound);
    std::vector<unsigned int> vertices(bound * kMeshletVertices);
    std::vector<unsigned char> local(bound * kMeshletTriangles * 3);
    meshlets.resize(
        meshopt_buildMeshlets(meshlets.data(), vertices.data(), local.data(), mesh.triangles.data(),
                              mesh.triangles.size(), &mesh.positions[0].x, mesh.positions.size(),
                              sizeof(glm::vec3), kMeshletVertices, kMeshletTriangles, kConeWeight));
    // Match the meshlets' triangles to the mesh's by their vertices: both lists sorted by key
    // (then by index, so repeated triangles pair off in order).
    std::vector<std::pair<TriangleKey, std::uint32_t>> original(tris), placed;
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        original[t] = {triangle_key(v[0], v[1], v[2]), static_cast<std::uint32_t>(t)};
    }
    placed.reserve(tris);
    for (std::size_t m = 0; m < meshlets.size(); ++m) {
        const meshopt_Meshlet& ml = meshlets[m];
        for (std::size_t t = 0; t < ml.triangle_count; ++t) {
            const unsigned char* l = &local[ml.triangle_offset + 3 * t];
            const unsigned int* mv = &vertices[ml.vertex_offset];
            placed.push_back(
                {triangle_key(mv[l[0]], mv[l[1]], mv[l[2]]), static_cast<std::uint32_t>(m)});
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
    if (std::isnan(e.cos_dihedral)) return 2.0f;
    return e.cos_dihedral >= 1.0f ? kFlatKey : e.cos_dihedral;
}

// A cluster of edges [first, first + count) of `c.edges`, its bounds around the candidates
// (the edges before the first flat one).
EdgeCluster bound_cluster(const AdjacencyMesh& mesh, const std::vector<glm::dvec3>& unit_normals,
                          const std::vector<bool>& degenerate, const ClusteredEdges& c,
                          std::uint32_t first, std::uint32_t all) {
    EdgeCluster out;
    out.first = first;
    out.count = all;
    std::uint32_t count = 0;
    while (count < all && c.crease_keys[first + count] < kFlatKey) ++count;
    out.candidates = count;
    if (count == 0) return out;
    glm::dvec3 lo(INFINITY), hi(-INFINITY), sum(0.0);
    bool cone = true;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const MeshEdge& e = c.edges[i];
        for (const std::uint32_t v : {e.a, e.b}) {
            lo = glm::min(lo, glm::dvec3(mesh.positions[v]));
            hi = glm::max(hi, glm::dvec3(mesh.positions[v]));
        }
        for (const std::uint32_t f : {e.face_a, e.face_b}) {
            if (f == kNoVertex) continue;
            if (degenerate[f]) cone = false;
            sum += unit_normals[f];
        }
    }
    const glm::dvec3 centre = (lo + hi) * 0.5;
    double radius = 0.0;
    for (std::uint32_t i = first; i < first + count; ++i) {
        for (const std::uint32_t v : {c.edges[i].a, c.edges[i].b})
            radius = std::max(radius, glm::length(glm::dvec3(mesh.positions[v]) - centre));
    }
    out.center = glm::vec3(centre);
    // Widened for the centre's rounding to float.
    out.radius = static_cast<float>(radius * (1.0 + 1e-6) +
                                    glm::length(glm::dvec3(out.center) - centre) + 1e-30);
    const double length = glm::length(sum);
    if (!cone || !(length > 1e-9)) return out;
    const glm::dvec3 axis = sum / length;
    double spread = 1.0;
    for (std::uint32_t i = first; i < first + count; ++i) {
        for (const std::uint32_t f : {c.edges[i].face_a, c.edges[i].face_b})
            if (f != kNoVertex) spread = std::min(spread, glm::dot(axis, unit_normals[f]));
    }
    spread -= kConeSlack;
    if (spread <= 0.0) return out;  // over a half-space: no view sees all of it one way
    out.axis = glm::vec3(axis);
    out.cos_spread = static_cast<float>(spread);
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

    const std::size_t tris = mesh.triangle_count();
    std::vector<glm::dvec3> unit_normals(tris, glm::dvec3(0.0));
    std::vector<bool> degenerate(tris, true);
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        const glm::dvec3 p0(mesh.positions[v[0]]);
        const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[v[1]]) - p0,
                                        glm::dvec3(mesh.positions[v[2]]) - p0);
        const double l = glm::length(n);
        // The shader's float normal of such a face may round to zero, or differ in direction.
        if (l > 1e-30 && std::isfinite(l)) {
            unit_normals[t] = n / l;
            degenerate[t] = false;
        }
    }

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
            out.clusters.push_back(
                bound_cluster(mesh, unit_normals, degenerate, out, first, to - from));
        }
    }
    return out;
}

std::uint32_t crease_prefix(const ClusteredEdges& c, const EdgeCluster& cluster, float cos_crease) {
    const auto begin = c.crease_keys.begin() + cluster.first;
    return static_cast<std::uint32_t>(std::lower_bound(begin, begin + cluster.count, cos_crease) -
                                      begin);
}

}  // namespace bz::geo
