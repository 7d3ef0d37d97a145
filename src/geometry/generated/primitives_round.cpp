// Primitives with rings of vertices: uv sphere and cylinder.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geometry/generated/primitives.h"

namespace bz::geo {
namespace {

// Direction around the y axis for column j of `segments`. The seam column (j == segments)
// reuses column 0's angle so the duplicated vertices are bit-identical.
glm::vec2 around(std::uint32_t j, std::uint32_t segments) {
    const double angle = 2.0 * std::numbers::pi * (j % segments) / segments;
    return {static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle))};
}

void check(bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string(what) + ": invalid size or count");
}

glm::vec3 sphere_point(float radius, std::uint32_t i, std::uint32_t j, std::uint32_t rings,
                       std::uint32_t segments) {
    // Poles are set exactly: sin(pi) is not zero in floating point.
    if (i == 0) return {0.0f, radius, 0.0f};
    if (i == rings) return {0.0f, -radius, 0.0f};
    const double polar = std::numbers::pi * i / rings;
    const auto ring = static_cast<float>(radius * std::sin(polar));
    const glm::vec2 d = around(j, segments);
    return {ring * d.x, static_cast<float>(radius * std::cos(polar)), ring * d.y};
}

void push(TriMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
}

}  // namespace

TriMesh uv_sphere(float radius, std::uint32_t rings, std::uint32_t segments) {
    check(radius > 0.0f && rings >= 2 && segments >= 3, "uv_sphere");
    TriMesh m;
    const std::uint32_t cols = segments + 1;
    for (std::uint32_t i = 0; i <= rings; ++i) {
        for (std::uint32_t j = 0; j <= segments; ++j) {
            m.positions.push_back(sphere_point(radius, i, j, rings, segments));
        }
    }
    // Quad (a b / c d) between rows i and i+1; (d c a) and (d a b) face outward. The pole
    // rows collapse one of the two, which is left out.
    for (std::uint32_t i = 0; i < rings; ++i) {
        for (std::uint32_t j = 0; j < segments; ++j) {
            const std::uint32_t a = i * cols + j, b = a + 1, c = a + cols, d = c + 1;
            if (i + 1 < rings) push(m, d, c, a);
            if (i > 0) push(m, d, a, b);
        }
    }
    return m;
}

TriMesh cylinder(float radius, float half_height, std::uint32_t segments) {
    check(radius > 0.0f && half_height > 0.0f && segments >= 3, "cylinder");
    TriMesh m;
    // Side: a bottom and a top vertex per column, seam column duplicated.
    for (std::uint32_t j = 0; j <= segments; ++j) {
        const glm::vec2 d = around(j, segments) * radius;
        m.positions.push_back({d.x, -half_height, d.y});
        m.positions.push_back({d.x, half_height, d.y});
    }
    for (std::uint32_t j = 0; j < segments; ++j) {
        const std::uint32_t b0 = 2 * j, t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
        push(m, b1, b0, t0);
        push(m, b1, t0, t1);
    }
    // Caps: a centre and a ring of their own each.
    for (const float y : {half_height, -half_height}) {
        const auto centre = static_cast<std::uint32_t>(m.positions.size());
        m.positions.push_back({0.0f, y, 0.0f});
        for (std::uint32_t j = 0; j < segments; ++j) {
            const glm::vec2 d = around(j, segments) * radius;
            m.positions.push_back({d.x, y, d.y});
        }
        for (std::uint32_t j = 0; j < segments; ++j) {
            const std::uint32_t p = centre + 1 + j, q = centre + 1 + (j + 1) % segments;
            if (y > 0)
                push(m, centre, q, p);
            else
                push(m, centre, p, q);
        }
    }
    return m;
}

}  // namespace bz::geo
