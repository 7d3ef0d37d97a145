#include "geometry/intersect/triangle_crossing.h"

#include <algorithm>
#include <cmath>

namespace bz::geo {

namespace {

// Distances below this fraction of the pair's size count as zero: a vertex "on" the plane.
constexpr double kRelativeZero = 1e-10;

// How one triangle lies against the other's plane.
struct Side {
    std::array<double, 3> d{};        // signed distances, zeroed within the tolerance
    bool crosses = false;             // vertices strictly on both sides
    bool touches_from_below = false;  // some on the plane, the rest strictly below it
};

Side side_of(const Triangle3& t, const glm::dvec3& unit_n, const glm::dvec3& on_plane,
             double zero) {
    Side s;
    int above = 0, below = 0;
    for (int i = 0; i < 3; ++i) {
        double d = glm::dot(unit_n, t[static_cast<std::size_t>(i)] - on_plane);
        if (std::abs(d) <= zero) d = 0.0;
        s.d[static_cast<std::size_t>(i)] = d;
        above += d > 0.0;
        below += d < 0.0;
    }
    s.crosses = above > 0 && below > 0;
    s.touches_from_below = above == 0 && below > 0 && below < 3;
    return s;
}

// The stretch of `t` on the other plane (zero distances `s.d`), as the two extreme points
// along the line direction `dir`, with their parameters.
struct Stretch {
    glm::dvec3 lo_point{0.0}, hi_point{0.0};
    double lo = 0.0, hi = 0.0;
};

Stretch stretch_on_plane(const Triangle3& t, const Side& s, const glm::dvec3& dir) {
    Stretch out;
    bool any = false;
    auto add = [&](const glm::dvec3& p) {
        const double k = glm::dot(p, dir);
        if (!any || k < out.lo) {
            out.lo = k;
            out.lo_point = p;
        }
        if (!any || k > out.hi) {
            out.hi = k;
            out.hi_point = p;
        }
        any = true;
    };
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3;
        if (s.d[i] == 0.0) add(t[i]);
        if ((s.d[i] < 0.0 && s.d[j] > 0.0) || (s.d[i] > 0.0 && s.d[j] < 0.0)) {
            const double f = s.d[i] / (s.d[i] - s.d[j]);
            add(t[i] + (t[j] - t[i]) * f);
        }
    }
    return out;
}

double longest_edge(const Triangle3& t) {
    return std::max({glm::length(t[1] - t[0]), glm::length(t[2] - t[1]), glm::length(t[0] - t[2])});
}

}  // namespace

std::optional<CrossingSegment> triangle_crossing(const Triangle3& t, const Triangle3& u) {
    const glm::dvec3 nt = glm::cross(t[1] - t[0], t[2] - t[0]);
    const glm::dvec3 nu = glm::cross(u[1] - u[0], u[2] - u[0]);
    const double lt = glm::length(nt), lu = glm::length(nu);
    if (!(lt > 0.0) || !(lu > 0.0) || !std::isfinite(lt) || !std::isfinite(lu)) return {};
    const double size = std::max(longest_edge(t), longest_edge(u));
    const double zero = kRelativeZero * size;
    const Side t_on_u = side_of(t, nu / lu, u[0], zero);
    if (!t_on_u.crosses && !t_on_u.touches_from_below) return {};
    const Side u_on_t = side_of(u, nt / lt, t[0], zero);
    if (!u_on_t.crosses && !u_on_t.touches_from_below) return {};
    // At least one must pass through the other: two that only touch meet along an edge or at
    // a vertex without crossing.
    if (!t_on_u.crosses && !u_on_t.crosses) return {};
    const glm::dvec3 dir = glm::cross(nt / lt, nu / lu);
    const double sin_angle = glm::length(dir);
    if (!(sin_angle > kRelativeZero)) return {};  // (nearly) parallel planes
    const glm::dvec3 unit_dir = dir / sin_angle;
    const Stretch st = stretch_on_plane(t, t_on_u, unit_dir);
    const Stretch su = stretch_on_plane(u, u_on_t, unit_dir);
    const double lo = std::max(st.lo, su.lo), hi = std::min(st.hi, su.hi);
    if (!(hi - lo > zero)) return {};
    // The ends on t's own stretch (exactly on t, within rounding on u).
    const double span = st.hi - st.lo;
    if (!(span > 0.0)) return {};
    auto at = [&](double k) {
        return st.lo_point + (st.hi_point - st.lo_point) * ((k - st.lo) / span);
    };
    return CrossingSegment{at(lo), at(hi)};
}

}  // namespace bz::geo
