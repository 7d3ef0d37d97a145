#include <glm/glm.hpp>

#include "geometry/line_mesh/clean.h"

namespace bz::geo {
namespace {

bool zero_area(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 pa(a);
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - pa, glm::dvec3(c) - pa);
    return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

}  // namespace

std::size_t remove_degenerate(const std::vector<glm::vec3>& positions,
                              std::vector<std::uint32_t>& triangles,
                              std::vector<std::uint32_t>* face_tags) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i + 2 < triangles.size(); i += 3) {
        const std::uint32_t a = triangles[i], b = triangles[i + 1], c = triangles[i + 2];
        if (a == b || b == c || c == a) continue;
        if (zero_area(positions[a], positions[b], positions[c])) continue;
        if (face_tags) (*face_tags)[kept / 3] = (*face_tags)[i / 3];
        triangles[kept] = a;
        triangles[kept + 1] = b;
        triangles[kept + 2] = c;
        kept += 3;
    }
    const std::size_t dropped = (triangles.size() - kept) / 3;
    triangles.resize(kept);
    if (face_tags) face_tags->resize(kept / 3);
    return dropped;
}

}  // namespace bz::geo
