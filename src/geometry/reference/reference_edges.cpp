#include "geometry/reference/reference_edges.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "geometry/intersect/intersection_lines.h"

namespace bz::geo::detail {

namespace {

glm::dvec3 face_normal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return glm::cross(b - a, c - a);
}

// The shader's test: the eye is the view-space origin, which stays right behind the camera.
bool front_facing(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return glm::dot(face_normal(a, b, c), -a) > 0.0;
}

// A zero normal (a degenerate face) stays zero, as in geometry/derived/dihedral.cpp.
glm::dvec3 unit(const glm::dvec3& n) {
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

glm::dvec3 object_pos(const AdjacencyMesh& m, std::uint32_t i) {
    return glm::dvec3(m.positions[i]);
}

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

}  // namespace

void find_feature_edges(const ReferenceInstance& inst, std::uint32_t instance_index,
                        const std::vector<glm::dvec3>& vp, std::vector<FeatureEdge>& out) {
    const AdjacencyMesh& m = *inst.mesh;
    // A non-interior edge is emitted by every face on it; one copy is enough for a mask.
    std::unordered_set<std::uint64_t> open_edges;
    const std::size_t tris = m.triangle_count();
    // The shaders' rule: material boundaries when asked, except past the creases' LOD.
    const bool materials = inst.material_lines && m.has_material_edges() && inst.cos_crease >= -1.0;
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* adj = &m.adjacency[t * 6];
        const glm::dvec3 n_view = face_normal(vp[adj[0]], vp[adj[2]], vp[adj[4]]);
        const bool front = glm::dot(n_view, -vp[adj[0]]) > 0.0;
        const glm::dvec3 n_obj =
            unit(face_normal(object_pos(m, adj[0]), object_pos(m, adj[2]), object_pos(m, adj[4])));
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t v0 = adj[2 * e], va = adj[2 * e + 1], v1 = adj[(2 * e + 2) % 6];
            FeatureEdge fe{vp[v0], vp[v1], instance_index, v0, v1, FeatureKind::boundary, {}};
            if (va == v0) {
                if (open_edges.insert(edge_key(v0, v1)).second) out.push_back(fe);
                continue;
            }
            const bool neighbour_front = front_facing(vp[v0], vp[va], vp[v1]);
            if (front && !neighbour_front) {
                fe.kind = FeatureKind::silhouette;
                out.push_back(fe);
                continue;
            }
            if (front != neighbour_front) continue;  // the other face owns this silhouette
            if (v0 > v1) continue;                   // each crease once
            // geometry/derived/dihedral.cpp's cosine, kept in double.
            const glm::dvec3 m_obj =
                unit(face_normal(object_pos(m, v0), object_pos(m, va), object_pos(m, v1)));
            if (glm::dot(n_obj, m_obj) < inst.cos_crease) {
                fe.kind = FeatureKind::crease;
                out.push_back(fe);
            } else if (materials && m.material_edges[t * 3 + static_cast<std::size_t>(e)]) {
                fe.kind = FeatureKind::material;
                out.push_back(fe);
            }
        }
    }
}

void find_intersection_edges(std::span<const ReferenceInstance> instances,
                             std::vector<FeatureEdge>& out) {
    // Only occluders: the GPU finds these lines' visibility against the depth prepass, which
    // holds nothing else, and a surface that hides nothing cuts nothing either. Each instance
    // still hides what lies behind it, whether it takes part or not.
    std::vector<PlacedMesh> placed;
    std::vector<std::uint32_t> index;  // placed -> instance
    for (std::size_t i = 0; i < instances.size(); ++i) {
        if (!instances[i].occluder || !instances[i].intersects) continue;
        placed.push_back(place_mesh(*instances[i].mesh, instances[i].model_view));
        index.push_back(static_cast<std::uint32_t>(i));
    }
    auto face = [&](std::uint32_t p, std::uint32_t t) {
        const std::uint32_t* v = &placed[p].mesh->triangles[3 * std::size_t{t}];
        return ExcludedFace{index[p], v[0], v[1], v[2]};
    };
    for (const SceneIntersection& x : scene_intersections(placed)) {
        out.push_back(
            {x.segment.a,
             x.segment.b,
             index[x.first],
             ~0u,
             ~0u,
             FeatureKind::intersection,
             {face(x.first, x.segment.triangle_a), face(x.second, x.segment.triangle_b)}});
    }
}

}  // namespace bz::geo::detail
