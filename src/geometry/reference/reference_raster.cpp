#include "geometry/reference/reference_raster.h"

#include <algorithm>
#include <cmath>

namespace bz::geo::detail {

namespace {

constexpr double kGuard = 2.0;  // lines.geom's lateral guard band

}  // namespace

Projection Projection::of(const ReferenceView& v) {
    Projection p;
    const double cot = 1.0 / std::tan(v.fov_y_deg * 3.14159265358979323846 / 360.0);
    p.px = cot / (static_cast<double>(v.width) / v.height);
    p.py = cot;
    p.width = v.width;
    p.height = v.height;
    p.near = v.near;
    p.far = v.far;
    return p;
}

glm::dvec3 ClippedEdge::at(double u) const {
    // Window positions are linear in u but view positions are linear in t; they meet through
    // the clip w of the two ends (perspective-correct interpolation).
    const double den = u * wa + (1.0 - u) * wb;
    const double t = den > 0.0 ? u * wa / den : u;
    return a + (b - a) * t;
}

std::optional<ClippedEdge> clip_edge(glm::dvec3 a, glm::dvec3 b, const Projection& p) {
    double da = -a.z, db = -b.z;
    if (da < p.near && db < p.near) return std::nullopt;
    if (da > p.far && db > p.far) return std::nullopt;
    if (da < p.near)
        a = glm::mix(a, b, (p.near - da) / (db - da));
    else if (db < p.near)
        b = glm::mix(b, a, (p.near - db) / (da - db));
    da = -a.z;
    db = -b.z;
    if (da > p.far)
        a = glm::mix(a, b, (da - p.far) / (da - db));
    else if (db > p.far)
        b = glm::mix(b, a, (db - p.far) / (db - da));

    // Clip space is affine in view space, so clipping there moves the view points alike.
    glm::dvec4 ca = p.clip(a), cb = p.clip(b);
    for (int axis = 0; axis < 2; ++axis) {
        for (int side = -1; side <= 1; side += 2) {
            const double fa = kGuard * ca.w - side * ca[axis];
            const double fb = kGuard * cb.w - side * cb[axis];
            if (fa < 0.0 && fb < 0.0) return std::nullopt;
            if (fa < 0.0) {
                const double t = fa / (fa - fb);
                ca = glm::mix(ca, cb, t);
                a = glm::mix(a, b, t);
            } else if (fb < 0.0) {
                const double t = fb / (fb - fa);
                cb = glm::mix(cb, ca, t);
                b = glm::mix(b, a, t);
            }
        }
    }
    ClippedEdge e;
    e.a = a;
    e.b = b;
    e.sa = p.window(ca);
    e.sb = p.window(cb);
    e.wa = ca.w;
    e.wb = cb.w;
    return e;
}

std::optional<glm::dvec2> clip_to_rect(glm::dvec2 sa, glm::dvec2 sb, glm::dvec2 lo, glm::dvec2 hi) {
    double u0 = 0.0, u1 = 1.0;
    const glm::dvec2 d = sb - sa;
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0.0) {
            if (sa[axis] < lo[axis] || sa[axis] > hi[axis]) return std::nullopt;
            continue;
        }
        double ta = (lo[axis] - sa[axis]) / d[axis];
        double tb = (hi[axis] - sa[axis]) / d[axis];
        if (ta > tb) std::swap(ta, tb);
        u0 = std::max(u0, ta);
        u1 = std::min(u1, tb);
        if (u0 > u1) return std::nullopt;
    }
    return glm::dvec2(u0, u1);
}

bool crosses_pixel(glm::dvec2 c, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
    if (hi.x < c.x - 0.5 || lo.x >= c.x + 0.5 || hi.y < c.y - 0.5 || lo.y >= c.y + 0.5)
        return false;
    const glm::dvec2 d = b - a;
    const glm::dvec2 n(-d.y, d.x);
    return std::abs(glm::dot(n, c - a)) <= 0.5 * (std::abs(n.x) + std::abs(n.y));
}

std::size_t mark_segment(std::vector<std::uint8_t>& mask, int width, int height, glm::dvec2 a,
                         glm::dvec2 b) {
    // Restrict to the viewport first so a segment reaching far outside costs nothing extra.
    const auto range = clip_to_rect(a, b, {-1.0, -1.0}, {width + 1.0, height + 1.0});
    if (!range) return 0;
    const glm::dvec2 ca = a + (b - a) * (*range)[0];
    const glm::dvec2 cb = a + (b - a) * (*range)[1];
    std::size_t added = 0;
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ca.y, cb.y))) - 1);
    const int y1 = std::min(height - 1, static_cast<int>(std::floor(std::max(ca.y, cb.y))) + 1);
    const glm::dvec2 d = cb - ca;
    for (int y = y0; y <= y1; ++y) {
        // The segment's x extent within this row (widened by one pixel each side for the test).
        double xlo = std::min(ca.x, cb.x), xhi = std::max(ca.x, cb.x);
        if (d.y != 0.0) {
            const double t0 = std::clamp((y - ca.y) / d.y, 0.0, 1.0);
            const double t1 = std::clamp((y + 1.0 - ca.y) / d.y, 0.0, 1.0);
            const double x0 = ca.x + d.x * t0, x1 = ca.x + d.x * t1;
            xlo = std::min(x0, x1);
            xhi = std::max(x0, x1);
        }
        const int xa = std::max(0, static_cast<int>(std::floor(xlo)) - 1);
        const int xb = std::min(width - 1, static_cast<int>(std::floor(xhi)) + 1);
        for (int x = xa; x <= xb; ++x) {
            if (!crosses_pixel({x + 0.5, y + 0.5}, a, b)) continue;
            auto& px =
                mask[static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) +
                     static_cast<std::size_t>(x)];
            if (!px) ++added;
            px = 255;
        }
    }
    return added;
}

}  // namespace bz::geo::detail
