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

// Per edge of a mesh's clustered edge list, what the facing test needs.
struct EdgeFacing {
    glm::vec3 a;    // vertex a, on both faces
    glm::vec3 n_a;  // face A's unnormalised normal (geo::face_normals, as edges.comp reads it)
    glm::vec3 n_b;  // face B's; zero without face B (the test is then unsure: kept)
};

// The same for every edge of the list, one array per component, so that a cluster's edges are
// tested a SIMD vector at a time (list_maybe_features), with the crease keys
// (geo::ClusteredEdges::crease_keys) beside them. Every array holds geo::kMaxClusterEdges more
// entries than the list has edges (zeros and key 2, read but never listed), so that a
// cluster's fixed-size block never reads past the end.
struct EdgeFacingTable {
    enum Column { ax, ay, az, nax, nay, naz, nbx, nby, nbz, crease_key, kColumns };
    std::vector<float> columns[kColumns];
    std::size_t edges = 0;  // edges of the list (each column holds edges + kMaxClusterEdges)
    EdgeFacing at(std::size_t e) const;
};

EdgeFacingTable build_edge_facing_table(const geo::AdjacencyMesh& mesh,
                                        const geo::ClusteredEdges& clusters,
                                        const std::vector<glm::vec4>& face_normals);

// Whether the frame's edges go through the CPU test first (RenderSettings::edge_prefilter).
bool uses_edge_prefilter(const RenderSettings& settings, bool software_rasteriser);

// Whether an edge (its facing record and crease key) may be a feature edge of an instance
// whose eye, in object space, is `eye`, with creases below `cos_crease`: false only where
// edges.comp would surely find it no feature (both faces clearly on one side of the eye, and
// no crease, boundary or material key below cos_crease). The definition, one edge at a time;
// the culling runs list_maybe_features, which the tests hold to it (written through an
// EdgeFacing per edge, GCC no longer vectorises the block).
bool may_be_feature(const EdgeFacing& f, float crease_key, const glm::vec3& eye, float cos_crease);

// may_be_feature for the table's edges [first, first + count), count <= geo::kMaxClusterEdges
// (one cluster): writes the indices of those that may be feature edges to `kept` in order and
// returns how many.
std::uint32_t list_maybe_features(const EdgeFacingTable& table, std::uint32_t first,
                                  std::uint32_t count, const glm::vec3& eye, float cos_crease,
                                  std::uint32_t* kept);

}  // namespace bz::render
