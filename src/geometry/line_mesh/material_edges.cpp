#include "geometry/line_mesh/material_edges.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace bz::geo {

std::vector<std::uint8_t> find_material_edges(std::span<const std::uint32_t> triangles,
                                              std::span<const EdgeKind> edge_kinds,
                                              std::span<const std::uint32_t> face_materials) {
    if (face_materials.empty()) return {};
    const std::size_t tris = triangles.size() / 3;
    if (face_materials.size() != tris || edge_kinds.size() != triangles.size() ||
        triangles.size() % 3 != 0) {
        throw std::invalid_argument("find_material_edges: sizes do not match the triangles");
    }
    // One material for every face: no boundary, and no table to build.
    const std::uint32_t first = face_materials.front();
    if (std::all_of(face_materials.begin(), face_materials.end(),
                    [first](std::uint32_t m) { return m == first; })) {
        return {};
    }
    // An interior edge is walked once each way by its two faces (adjacency.h), so the face
    // across a -> b is the one that walks b -> a.
    const auto key = [](std::uint64_t from, std::uint64_t to) { return (from << 32) | to; };
    std::unordered_map<std::uint64_t, std::uint32_t> face_of;
    face_of.reserve(triangles.size());
    for (std::size_t h = 0; h < triangles.size(); ++h) {
        if (edge_kinds[h] != EdgeKind::interior) continue;
        const std::size_t t = h / 3;
        face_of.emplace(key(triangles[h], triangles[t * 3 + (h + 1) % 3]),
                        static_cast<std::uint32_t>(t));
    }
    std::vector<std::uint8_t> marks(triangles.size(), 0);
    bool any = false;
    for (std::size_t h = 0; h < triangles.size(); ++h) {
        if (edge_kinds[h] != EdgeKind::interior) continue;
        const std::size_t t = h / 3;
        const auto across = face_of.find(key(triangles[t * 3 + (h + 1) % 3], triangles[h]));
        if (across == face_of.end()) continue;  // cannot happen for an interior edge
        if (face_materials[across->second] != face_materials[t]) {
            marks[h] = 1;
            any = true;
        }
    }
    if (!any) return {};
    return marks;
}

}  // namespace bz::geo
