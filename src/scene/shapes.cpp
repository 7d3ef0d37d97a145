#include "scene/shapes.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace bz::scene::shapes {

namespace {

std::uint32_t push(geo::TriMesh& m, glm::vec3 p) {
    m.positions.push_back(p);
    return static_cast<std::uint32_t>(m.positions.size() - 1);
}

void tri(geo::TriMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
}

}  // namespace

geo::TriMesh loft(const std::vector<Ring>& rings) {
    if (rings.size() < 2) throw std::invalid_argument("loft needs at least two rings");
    std::size_t n = 0;
    for (const Ring& r : rings) {
        if (r.xz.size() == 1) continue;
        if (r.xz.size() < 3) throw std::invalid_argument("loft ring needs 1 or >= 3 points");
        if (n != 0 && r.xz.size() != n) throw std::invalid_argument("loft rings differ in size");
        n = r.xz.size();
    }
    if (n == 0) throw std::invalid_argument("loft needs one ring that is not an apex");

    geo::TriMesh m;
    std::vector<std::vector<std::uint32_t>> ids;
    for (const Ring& r : rings) {
        std::vector<std::uint32_t> ring_ids;
        for (glm::vec2 p : r.xz) ring_ids.push_back(push(m, {p.x, r.y, p.y}));
        ids.push_back(std::move(ring_ids));
    }
    // Rings run counter-clockwise seen from above, so (a, b, upper b) faces outwards.
    for (std::size_t k = 0; k + 1 < rings.size(); ++k) {
        const auto& lo = ids[k];
        const auto& hi = ids[k + 1];
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            if (lo.size() == 1 && hi.size() == 1)
                throw std::invalid_argument("two apexes in a row");
            if (lo.size() == 1) {
                tri(m, lo[0], hi[j], hi[i]);
            } else if (hi.size() == 1) {
                tri(m, lo[i], lo[j], hi[0]);
            } else {
                tri(m, lo[i], lo[j], hi[j]);
                tri(m, lo[i], hi[j], hi[i]);
            }
        }
    }
    const auto& first = ids.front();
    if (first.size() > 1) {  // bottom cap faces down: reverse the fan
        for (std::size_t i = 1; i + 1 < n; ++i) tri(m, first[0], first[i + 1], first[i]);
    }
    const auto& last = ids.back();
    if (last.size() > 1) {
        for (std::size_t i = 1; i + 1 < n; ++i) tri(m, last[0], last[i], last[i + 1]);
    }
    return m;
}

Ring ellipse_ring(int sides, glm::vec2 radii, float y, glm::vec2 center, float phase) {
    Ring r;
    r.y = y;
    for (int i = 0; i < sides; ++i) {
        const double a = phase + 2.0 * std::numbers::pi * i / sides;
        // Counter-clockwise seen from above: x = cos, z = -sin.
        r.xz.push_back(center + glm::vec2(radii.x * static_cast<float>(std::cos(a)),
                                          -radii.y * static_cast<float>(std::sin(a))));
    }
    return r;
}

Ring rect_ring(float width, float length, float y, glm::vec2 center) {
    const float hx = width * 0.5f;
    const float hz = length * 0.5f;
    return Ring{{center + glm::vec2(hx, hz), center + glm::vec2(hx, -hz),
                 center + glm::vec2(-hx, -hz), center + glm::vec2(-hx, hz)},
                y};
}

geo::TriMesh box(glm::vec3 min, glm::vec3 max) {
    const glm::vec2 c{(min.x + max.x) * 0.5f, (min.z + max.z) * 0.5f};
    const float w = max.x - min.x;
    const float l = max.z - min.z;
    return loft({rect_ring(w, l, min.y, c), rect_ring(w, l, max.y, c)});
}

geo::TriMesh strip(const std::vector<glm::vec3>& lower, const std::vector<glm::vec3>& upper,
                   bool closed) {
    if (lower.size() != upper.size() || lower.size() < 2) {
        throw std::invalid_argument("strip needs two polylines of equal length >= 2");
    }
    geo::TriMesh m;
    const std::size_t n = lower.size();
    for (std::size_t i = 0; i < n; ++i) push(m, lower[i]);
    for (std::size_t i = 0; i < n; ++i) push(m, upper[i]);
    const std::size_t segments = closed ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const auto a = static_cast<std::uint32_t>(i);
        const auto b = static_cast<std::uint32_t>((i + 1) % n);
        const auto c = static_cast<std::uint32_t>(n + (i + 1) % n);
        const auto d = static_cast<std::uint32_t>(n + i);
        tri(m, a, b, c);
        tri(m, a, c, d);
    }
    return m;
}

void append(geo::TriMesh& dst, const geo::TriMesh& src, const glm::mat4& m) {
    const auto base = static_cast<std::uint32_t>(dst.positions.size());
    for (glm::vec3 p : src.positions) dst.positions.push_back(glm::vec3(m * glm::vec4(p, 1.0f)));
    for (std::uint32_t i : src.indices) dst.indices.push_back(base + i);
}

double signed_volume(const geo::TriMesh& mesh) {
    double v = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a = mesh.positions[mesh.indices[t]];
        const glm::dvec3 b = mesh.positions[mesh.indices[t + 1]];
        const glm::dvec3 c = mesh.positions[mesh.indices[t + 2]];
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

}  // namespace bz::scene::shapes
