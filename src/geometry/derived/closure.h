#pragma once
#include "geometry/mesh.h"

namespace bz::geo {

// True when every edge has exactly one consistently wound neighbour (watertight) and the
// enclosed signed volume is positive (faces point outward). For such a mesh seen from outside
// its bounds, every back-facing triangle is hidden by the mesh itself, so the renderer may
// skip back faces in both the prepass and the line pass without changing the picture.
bool is_outward_closed(const AdjacencyMesh& mesh);

}  // namespace bz::geo
