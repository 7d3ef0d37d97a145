#pragma once
// On a software rasteriser (llvmpipe) edges.comp is CPU work run by a JIT that executes every
// branch of the shader for every SIMD vector, so an edge that turns out to be no feature costs
// nearly as much as one that is: Suzanne's 90,925 tested edges took 10-12 ms there for 4,365
// feature edges. The CPU rules most of them out in a tight loop first, and lists only the rest
// for edges.comp, which still classifies each listed edge itself: the test here only ever
// keeps more than the shader would draw (a margin twice the shader's own tie band), never
// fewer, so the lines are the shader's whatever this decides.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/derived/edge_clusters.h"
#include "render/settings.h"

namespace bz::geo {
struct AdjacencyMesh;
}

namespace bz::render {

// Per edge of a mesh's clustered edge list, what the facing test needs, side by side so that
// the test streams through memory (an index into the face normals instead cost twice the time
// on Suzanne, a cache miss an edge).
struct EdgeFacing {
    glm::vec3 a;    // vertex a, on both faces
    glm::vec3 n_a;  // face A's unnormalised normal (geo::face_normals, as edges.comp reads it)
    glm::vec3 n_b;  // face B's; zero without face B (the test is then unsure: kept)
};

// The crease keys it needs too are the clustered list's own (geo::ClusteredEdges::crease_keys).
struct EdgeFacingTable {
    std::vector<EdgeFacing> edges;  // in the clustered list's order
};

EdgeFacingTable build_edge_facing_table(const geo::AdjacencyMesh& mesh,
                                        const geo::ClusteredEdges& clusters,
                                        const std::vector<glm::vec4>& face_normals);

// Whether the frame's edges go through the CPU test first (RenderSettings::edge_prefilter).
bool uses_edge_prefilter(const RenderSettings& settings, bool software_rasteriser);

// Whether an edge (its facing record and crease key) may be a feature edge of an instance
// whose eye, in object space, is `eye`, with creases below `cos_crease`: false only where
// edges.comp would surely find it no feature (both faces clearly on one side of the eye, and
// no crease, boundary or material key below cos_crease).
bool may_be_feature(const EdgeFacing& f, float crease_key, const glm::vec3& eye, float cos_crease);

}  // namespace bz::render
