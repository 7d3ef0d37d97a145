#pragma once
// From an imported or generated triangle list to the welded, cleaned adjacency mesh that the
// line renderer draws.
#include "geometry/mesh.h"

namespace bz::geo {

// Welds by exact position (-0.0 == +0.0), drops degenerate triangles, exact duplicates and one
// face of each back-to-back twin pair (see clean.h), drops unused vertices, then builds
// adjacency (see adjacency.h). Positions keep their order of first use by the indices, and
// triangles keep their input order, so the same input always gives the same output.
// The report's edge counts count distinct edges, not triangle edges. The mesh's face materials,
// when it has them, mark the material boundaries (AdjacencyMesh::material_edges).
// Throws std::invalid_argument on an index out of range or a material count that is not the
// triangle count.
AdjacencyMesh build_line_mesh(const TriMesh& mesh, MeshReport* report = nullptr);

}  // namespace bz::geo
