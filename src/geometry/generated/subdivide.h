#pragma once
// Flat subdivision for scaling benchmarks: every triangle split into four at its edge
// midpoints, `levels` times (4^levels the triangles). The surface does not move and the new
// inner edges are flat, so the feature lines, and the image, stay the same.
#include "geometry/mesh.h"

namespace bz::geo {

// Throws std::invalid_argument for levels outside [0, 6].
AdjacencyMesh subdivide_flat(const AdjacencyMesh& mesh, int levels);

}  // namespace bz::geo
