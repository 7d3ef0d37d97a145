#include "render/lines/edge_prefilter.h"

#include <cmath>

#include "geometry/derived/edge_list.h"

namespace bz::render {

namespace {

// edges.comp decides facing by the sign of dot(n, eye - a) when it exceeds 1e-4 |n| |eye - a|
// and falls back to a view-space test below; the same float expression here differs from
// the shader's by a few units in the last place, so twice that band leaves no doubt.
constexpr float kUnsure = 2e-4f;

// +1 facing the eye, -1 facing away, 0 too near the plane to say.
int facing(const glm::vec3& n, const glm::vec3& to_eye) {
    const float s = glm::dot(n, to_eye);
    const float band = kUnsure * kUnsure * glm::dot(n, n) * glm::dot(to_eye, to_eye);
    if (!(s * s > band)) return 0;  // NaN too
    return s > 0.0f ? 1 : -1;
}

}  // namespace

EdgeFacingTable build_edge_facing_table(const geo::AdjacencyMesh& mesh,
                                        const geo::ClusteredEdges& clusters,
                                        const std::vector<glm::vec4>& face_normals) {
    EdgeFacingTable p;
    p.edges.reserve(clusters.edges.size());
    for (const geo::MeshEdge& e : clusters.edges) {
        // edges.comp's test for face B (both its opposite vertex and its triangle)
        const bool has_b = e.opp_b != geo::kNoVertex && e.face_b != geo::kNoVertex;
        p.edges.push_back({mesh.positions[e.a], glm::vec3(face_normals[e.face_a]),
                           has_b ? glm::vec3(face_normals[e.face_b]) : glm::vec3(0.0f)});
    }
    return p;
}

bool uses_edge_prefilter(const RenderSettings& settings, bool software_rasteriser) {
    switch (settings.edge_prefilter) {
        case EdgePrefilter::gpu:
            return false;
        case EdgePrefilter::cpu:
            return true;
        case EdgePrefilter::automatic:
            break;
    }
    return software_rasteriser;
}

bool may_be_feature(const EdgeFacing& f, float crease_key, const glm::vec3& eye, float cos_crease) {
    // Creases, boundaries and material boundaries sort below any crease threshold they pass.
    if (crease_key < cos_crease) return true;
    const glm::vec3 to_eye = eye - f.a;
    const int a = facing(f.n_a, to_eye);
    if (a == 0) return true;
    const int b = facing(f.n_b, to_eye);
    return b != a;  // a silhouette, or unsure
}

}  // namespace bz::render
