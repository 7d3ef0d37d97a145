#pragma once
// The screen side of the CPU reference: clipping an edge the way the geometry shader does,
// mapping between screen and view-space positions along it, and marking crossed pixels.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "geometry/reference/reference.h"

namespace bz::geo::detail {

struct Projection {
    double px = 1.0;  // proj[0][0] = cot(fov / 2) / aspect
    double py = 1.0;  // proj[1][1] = cot(fov / 2)
    int width = 1;
    int height = 1;
    double near = 0.1;
    double far = 1000.0;
    static Projection of(const ReferenceView& view);
    glm::dvec4 clip(const glm::dvec3& v) const { return {v.x * px, v.y * py, 0.0, -v.z}; }
    glm::dvec2 window(const glm::dvec4& c) const {
        return {(c.x / c.w * 0.5 + 0.5) * width, (c.y / c.w * 0.5 + 0.5) * height};
    }
};

// An edge after clipping: view-space end points and their window positions.
struct ClippedEdge {
    glm::dvec3 a{0.0}, b{0.0};
    glm::dvec2 sa{0.0}, sb{0.0};
    double wa = 1.0, wb = 1.0;  // clip w (view depth) at a and b
    // The view-space point whose window position is sa + u * (sb - sa).
    glm::dvec3 at(double u) const;
};

// Near/far planes in view space, then the lateral guard band |x|,|y| <= 2w (lines.geom).
std::optional<ClippedEdge> clip_edge(glm::dvec3 a, glm::dvec3 b, const Projection& p);

// The part [u0, u1] of segment sa-sb that lies within the rectangle lo..hi; nothing if none.
std::optional<glm::dvec2> clip_to_rect(glm::dvec2 sa, glm::dvec2 sb, glm::dvec2 lo, glm::dvec2 hi);

// The mask shader's rule: segment a-b meets the unit pixel square centred on c.
bool crosses_pixel(glm::dvec2 c, glm::dvec2 a, glm::dvec2 b);

// Sets every pixel segment a-b (window coordinates) crosses to 255; returns how many it set
// that were 0. `mask` is width * height, row 0 at the top.
std::size_t mark_segment(std::vector<std::uint8_t>& mask, int width, int height, glm::dvec2 a,
                         glm::dvec2 b);

}  // namespace bz::geo::detail
