#include "geometry/derived/edge_list.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "geometry/derived/dihedral.h"

namespace bz::geo {

std::vector<MeshEdge> build_edge_list(const AdjacencyMesh& mesh) {
    const std::size_t tris = mesh.triangle_count();
    const std::vector<float> cosines = edge_dihedral_cosines(mesh);
    // Face B of an interior edge a -> b (a < b) is the triangle that walks b -> a.
    const auto key = [](std::uint64_t from, std::uint64_t to) { return (from << 32) | to; };
    std::unordered_map<std::uint64_t, std::uint32_t> high_to_low;
    high_to_low.reserve(tris * 3 / 2 + 16);
    for (std::size_t t = 0; t < tris; ++t) {
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t from = mesh.triangles[t * 3 + e];
            const std::uint32_t to = mesh.triangles[t * 3 + (e + 1) % 3];
            if (mesh.edge_kinds[t * 3 + e] == EdgeKind::interior && from > to)
                high_to_low.emplace(key(from, to), static_cast<std::uint32_t>(t));
        }
    }
    std::vector<MeshEdge> edges;
    edges.reserve(tris * 3 / 2 + 16);
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* adj = &mesh.adjacency[t * 6];
        for (int e = 0; e < 3; ++e) {
            const std::size_t slot = t * 3 + static_cast<std::size_t>(e);
            MeshEdge m;
            m.a = adj[2 * e];
            m.b = adj[(2 * e + 2) % 6];
            m.opp_a = adj[(2 * e + 4) % 6];
            m.face_a = static_cast<std::uint32_t>(t);
            const EdgeKind kind = mesh.edge_kinds[slot];
            if (kind == EdgeKind::interior) {
                // The neighbour walks b -> a, so exactly one of the two half-edges runs low ->
                // high.
                if (m.a > m.b) continue;
                m.opp_b = adj[2 * e + 1];
                m.cos_dihedral = cosines[slot];
                const auto b_side = high_to_low.find(key(m.b, m.a));
                // Always found: build_line_mesh marks an edge interior only with its twin.
                if (b_side != high_to_low.end()) m.face_b = b_side->second;
                if (mesh.has_material_edges() && mesh.material_edges[slot])
                    m.flags |= kEdgeMaterialBoundary;
            } else {
                m.flags = static_cast<std::uint32_t>(kind);
            }
            m.id = static_cast<std::uint32_t>(edges.size());
            edges.push_back(m);
        }
    }
    return edges;
}

std::vector<glm::vec4> face_normals(const AdjacencyMesh& mesh) {
    std::vector<glm::vec4> out(mesh.triangle_count());
    for (std::size_t t = 0; t < out.size(); ++t) {
        const std::uint32_t* v = &mesh.triangles[t * 3];
        const glm::dvec3 p0(mesh.positions[v[0]]), p1(mesh.positions[v[1]]),
            p2(mesh.positions[v[2]]);
        const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
        out[t] = glm::vec4(glm::vec3(n), 0.0f);
    }
    return out;
}

std::vector<glm::vec3> vertex_normals(const AdjacencyMesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const std::uint32_t* v = &mesh.triangles[t * 3];
        const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[v[0]]), glm::dvec3(mesh.positions[v[1]]),
                                 glm::dvec3(mesh.positions[v[2]])};
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double len = glm::length(n);
        if (!(len > 0.0)) continue;
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3 u = p[(i + 1) % 3] - p[i], w = p[(i + 2) % 3] - p[i];
            const double lu = glm::length(u), lw = glm::length(w);
            if (!(lu > 0.0 && lw > 0.0)) continue;
            const double angle = std::acos(std::clamp(glm::dot(u, w) / (lu * lw), -1.0, 1.0));
            sum[v[i]] += n / len * angle;
        }
    }
    std::vector<glm::vec3> out(sum.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double len = glm::length(sum[i]);
        if (len > 0.0) out[i] = glm::vec3(sum[i] / len);
    }
    return out;
}

}  // namespace bz::geo
