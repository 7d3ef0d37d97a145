#pragma once
// Choosing which face of each back-to-back pair survives (see remove_coincident_faces).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace bz::geo::detail {

struct TwinPair {
    std::uint32_t first;   // the face that comes first in the triangle list
    std::uint32_t second;  // the same three vertices, wound the other way
};

// Sets dropped[face] = 1 for the losing face of every pair. On entry dropped marks faces that
// are already gone (duplicates); they take no part. Returns the number of faces dropped.
std::size_t resolve_twins(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                          std::span<const TwinPair> pairs, std::vector<std::uint8_t>& dropped);

}  // namespace bz::geo::detail
