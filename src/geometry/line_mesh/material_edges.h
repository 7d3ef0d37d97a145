#pragma once
// Material boundaries: the interior edges whose two faces have different materials. They are
// view-independent like creases, so they are found once per mesh (build_line_mesh) and the
// line renderer and the CPU reference only read the per-edge mark.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

// 3 marks per triangle (edge i = v_i -> v_{i+1}): 1 where the edge is EdgeKind::interior and
// the face across it has another material than this one, else 0. Only interior edges count:
// boundary, non-manifold and inconsistent edges are drawn whatever their materials.
// Empty when `face_materials` is empty or no edge is a material boundary (one material).
// Throws std::invalid_argument when the sizes do not match (one material per triangle, one
// kind per triangle edge).
std::vector<std::uint8_t> find_material_edges(std::span<const std::uint32_t> triangles,
                                              std::span<const EdgeKind> edge_kinds,
                                              std::span<const std::uint32_t> face_materials);

}  // namespace bz::geo
