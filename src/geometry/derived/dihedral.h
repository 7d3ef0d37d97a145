#pragma once
// View-independent edge data the line shader would otherwise recompute every frame: the
// cosine of the angle between the normals of the two faces on each triangle edge.
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

// 3 values per triangle (edge i = v_i -> v_{i+1}), computed in double from unit normals.
// Non-interior edges (no usable neighbour) get 2.0, above any threshold cosine.
std::vector<float> edge_dihedral_cosines(const AdjacencyMesh& mesh);

}  // namespace bz::geo
