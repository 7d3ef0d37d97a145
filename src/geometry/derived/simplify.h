#pragma once
// Simplified meshes for distance LOD (meshoptimizer's edge-collapse simplifier).
#include <optional>

#include "geometry/mesh.h"

namespace bz::geo {

struct SimplifyOptions {
    float triangle_ratio = 0.25f;    // aim for this fraction of the triangles
    float max_error = 0.02f;         // relative to the mesh's extent (meshopt_simplifyScale)
    std::size_t min_triangles = 64;  // smaller meshes are drawn as they are
    float min_gain = 0.7f;           // keep the result only below this fraction of the triangles
};

// A welded adjacency mesh with fewer triangles, or nothing when the mesh is small or the
// simplifier could not reduce it enough within the error. Boundary edges are kept in place
// (they are always feature lines).
std::optional<AdjacencyMesh> simplify_line_mesh(const AdjacencyMesh& mesh,
                                                const SimplifyOptions& options = {});

}  // namespace bz::geo
