#pragma once
// Cleaning steps between welding and adjacency. Each works on a welded triangle list (3 indices
// per triangle) in place and keeps the surviving triangles in their original order.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace bz::geo {

// Drops triangles that repeat a vertex or whose area is exactly zero (cross product computed
// in double, so only truly collinear corners count). Returns how many were dropped.
// `face_tags` (one per triangle, e.g. its material), when given, is kept in step.
std::size_t remove_degenerate(const std::vector<glm::vec3>& positions,
                              std::vector<std::uint32_t>& triangles,
                              std::vector<std::uint32_t>* face_tags = nullptr);

struct CoincidentCounts {
    std::size_t duplicates = 0;  // same vertices, same winding: all but the first dropped
    std::size_t twins = 0;       // back-to-back faces dropped (one per pair)
};

// Finds faces with the same three vertices. Exact duplicates (same winding) keep the first.
// Of two back-to-back twins (opposite winding) the one kept is the one whose winding agrees
// with more of the settled faces across its edges; faces settled this way vote for the twins
// next to them, so a twin-faced region takes the winding of the single-sided surface it
// touches. A region with no such surface keeps the first face of its first pair and spreads
// that winding. Expected O(n). `face_tags` (one per triangle), when given, is kept in step:
// a kept face keeps its own tag.
CoincidentCounts remove_coincident_faces(std::vector<std::uint32_t>& triangles,
                                         std::size_t vertex_count,
                                         std::vector<std::uint32_t>* face_tags = nullptr);

// Drops vertices no triangle uses and renumbers the rest in order of first use.
void compact_vertices(std::vector<glm::vec3>& positions, std::vector<std::uint32_t>& triangles);

}  // namespace bz::geo
