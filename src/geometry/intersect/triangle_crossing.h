#pragma once
// Where two triangles cross: the segment that lies on both, in double precision. Shared by the
// exact reference and the renderer's intersection lines (intersection_lines.h).
#include <array>
#include <glm/glm.hpp>
#include <optional>

namespace bz::geo {

using Triangle3 = std::array<glm::dvec3, 3>;

struct CrossingSegment {
    glm::dvec3 a{0.0};
    glm::dvec3 b{0.0};
};

// The segment where triangle `t` and triangle `u` cross, if they do along a stretch longer
// than rounding. No segment for:
//  - coplanar triangles (overlapping or not): no surface passes through the other;
//  - triangles that only touch: along a shared edge or at a shared vertex, or with an edge or
//    vertex lying on the other's plane while the rest stays on one side (a box resting on a
//    plane, two faces meeting at a ridge);
//  - degenerate triangles.
// A triangle whose edge lies on the other's plane while the other passes through it crosses
// there only if the rest of it lies below that plane (the side its normal points away from),
// so that of the two triangles on either side of such an edge exactly one reports the stretch.
std::optional<CrossingSegment> triangle_crossing(const Triangle3& t, const Triangle3& u);

}  // namespace bz::geo
