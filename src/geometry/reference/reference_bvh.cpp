#include "geometry/reference/reference_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bz::geo::detail {

namespace {

constexpr std::uint32_t kLeafSize = 4;
constexpr int kMaxDepth = 60;
// Barycentric slack: rays through the shared edge of two triangles hit at least one of them
// despite rounding.
constexpr double kEdgeSlack = 1e-12;

glm::dvec3 centroid(const BvhTriangle& t) {
    return (t.p0 + t.p1 + t.p2) / 3.0;
}

bool is_face(const BvhTriangle& t, const ExcludedFace& f) {
    return t.instance == f.instance && t.v0 == f.v0 && t.v1 == f.v1 && t.v2 == f.v2;
}

bool excluded_by(const BvhTriangle& t, const ExcludedEdge& e) {
    if (is_face(t, e.faces[0]) || is_face(t, e.faces[1])) return true;
    if (t.instance != e.instance) return false;
    const bool has_a = t.v0 == e.va || t.v1 == e.va || t.v2 == e.va;
    const bool has_b = t.v0 == e.vb || t.v1 == e.vb || t.v2 == e.vb;
    return has_a && has_b;
}

// Slab test of the segment's [t_min, t_max] against a box.
bool hits_box(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& origin,
              const glm::dvec3& inv_dir, double t_min, double t_max) {
    for (int a = 0; a < 3; ++a) {
        double t0 = (lo[a] - origin[a]) * inv_dir[a];
        double t1 = (hi[a] - origin[a]) * inv_dir[a];
        if (std::isnan(t0) || std::isnan(t1)) {
            // 0 * inf: the segment runs inside this slab's plane; it overlaps iff inside.
            if (origin[a] < lo[a] || origin[a] > hi[a]) return false;
            continue;
        }
        if (t0 > t1) std::swap(t0, t1);
        t_min = std::max(t_min, t0);
        t_max = std::min(t_max, t1);
        if (t_min > t_max) return false;
    }
    return true;
}

}  // namespace

double intersect(const BvhTriangle& tri, const glm::dvec3& origin, const glm::dvec3& dir) {
    const glm::dvec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0 || !std::isfinite(det)) return -1.0;  // parallel to the plane
    const double inv = 1.0 / det;
    const glm::dvec3 s = origin - tri.p0;
    const double u = glm::dot(s, p) * inv;
    if (u < -kEdgeSlack || u > 1.0 + kEdgeSlack) return -1.0;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) * inv;
    if (v < -kEdgeSlack || u + v > 1.0 + kEdgeSlack) return -1.0;
    return glm::dot(e2, q) * inv;
}

TriangleBvh::TriangleBvh(std::vector<BvhTriangle> triangles) : triangles_(std::move(triangles)) {
    nodes_.reserve(triangles_.size() / kLeafSize * 2 + 1);
    if (!triangles_.empty()) build(0, static_cast<std::uint32_t>(triangles_.size()), 0);
}

std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count, int depth) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    glm::dvec3 lo(std::numeric_limits<double>::infinity()),
        hi(-std::numeric_limits<double>::infinity());
    glm::dvec3 clo = lo, chi = hi;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const BvhTriangle& t = triangles_[i];
        lo = glm::min(lo, glm::min(t.p0, glm::min(t.p1, t.p2)));
        hi = glm::max(hi, glm::max(t.p0, glm::max(t.p1, t.p2)));
        const glm::dvec3 c = centroid(t);
        clo = glm::min(clo, c);
        chi = glm::max(chi, c);
    }
    nodes_[index].lo = lo;
    nodes_[index].hi = hi;
    const glm::dvec3 extent = chi - clo;
    if (count <= kLeafSize || depth >= kMaxDepth || extent == glm::dvec3(0.0)) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t half = count / 2;
    std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half,
                     triangles_.begin() + first + count,
                     [axis](const BvhTriangle& a, const BvhTriangle& b) {
                         return centroid(a)[axis] < centroid(b)[axis];
                     });
    build(first, half, depth + 1);
    const std::uint32_t right = build(first + half, count - half, depth + 1);
    nodes_[index].first = right;
    nodes_[index].count = 0;
    return index;
}

bool TriangleBvh::any_hit(const glm::dvec3& origin, const glm::dvec3& dir, double t_min,
                          double t_max, const ExcludedEdge& excluded) const {
    if (nodes_.empty() || !(t_min <= t_max)) return false;
    const glm::dvec3 inv_dir = 1.0 / dir;
    std::array<std::uint32_t, 2 * kMaxDepth + 8> stack{};
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (!hits_box(n.lo, n.hi, origin, inv_dir, t_min, t_max)) continue;
        if (n.count == 0) {
            const auto self = static_cast<std::uint32_t>(&n - nodes_.data());
            stack[top++] = n.first;
            stack[top++] = self + 1;
            continue;
        }
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
            const BvhTriangle& t = triangles_[i];
            if (excluded_by(t, excluded)) continue;
            const double hit = intersect(t, origin, dir);
            if (hit >= t_min && hit <= t_max) return true;
        }
    }
    return false;
}

int TriangleBvh::count_front_hits(const glm::dvec3& origin, const glm::dvec3& dir, double t_min,
                                  double t_max, const ExcludedEdge& excluded, int cap) const {
    if (nodes_.empty() || !(t_min <= t_max) || cap <= 0) return 0;
    const glm::dvec3 inv_dir = 1.0 / dir;
    std::array<std::uint32_t, 2 * kMaxDepth + 8> stack{};
    std::size_t top = 0;
    stack[top++] = 0;
    std::vector<double> hits;  // t of each front-facing hit
    // Enough distinct hits to reach the cap even if each surface is hit at a shared edge
    // (twice) or a corner (a few times): stop collecting there.
    const std::size_t enough = static_cast<std::size_t>(cap) * 8;
    while (top > 0 && hits.size() < enough) {
        const Node& n = nodes_[stack[--top]];
        if (!hits_box(n.lo, n.hi, origin, inv_dir, t_min, t_max)) continue;
        if (n.count == 0) {
            const auto self = static_cast<std::uint32_t>(&n - nodes_.data());
            stack[top++] = n.first;
            stack[top++] = self + 1;
            continue;
        }
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
            const BvhTriangle& t = triangles_[i];
            if (excluded_by(t, excluded)) continue;
            const double hit = intersect(t, origin, dir);
            if (!(hit >= t_min && hit <= t_max)) continue;
            const glm::dvec3 normal = glm::cross(t.p1 - t.p0, t.p2 - t.p0);
            if (glm::dot(normal, origin - t.p0) > 0.0) hits.push_back(hit);
        }
    }
    std::sort(hits.begin(), hits.end());
    int count = 0;
    double last = -1.0;
    for (const double h : hits) {
        if (count > 0 && h - last <= 1e-9 * std::max(1.0, std::abs(h))) continue;
        last = h;
        if (++count >= cap) break;
    }
    return count;
}

}  // namespace bz::geo::detail
