#pragma once
// Welding by exact position: vertices that a file split for normals or UVs become one again, so
// seams are not mistaken for boundaries.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

struct WeldedMesh {
    std::vector<glm::vec3> positions;      // unique, in order of first use by the indices
    std::vector<std::uint32_t> triangles;  // same triangles as the input, into positions
};

// Merges vertices whose positions are bit-identical after mapping -0.0 to +0.0. Vertices no
// triangle uses are dropped. Expected O(n) (one hash probe per distinct input vertex).
// Throws std::invalid_argument when an index is out of range or the index count is not a
// multiple of 3.
WeldedMesh weld_positions(const TriMesh& mesh);

}  // namespace bz::geo
