#include "geometry/intersect/intersection_lines.h"

#include <algorithm>
#include <cmath>

#include "geometry/intersect/triangle_crossing.h"

namespace bz::geo {

namespace {

DBox box_of(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return {glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))};
}

DBox intersect_boxes(const DBox& a, const DBox& b) {
    return {glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)};
}

Triangle3 triangle(const PlacedMesh& m, std::uint32_t t) {
    const std::uint32_t* v = &m.mesh->triangles[3 * std::size_t{t}];
    return {m.positions[v[0]], m.positions[v[1]], m.positions[v[2]]};
}

// The triangles of `m` whose bounds meet `box`.
std::vector<std::uint32_t> triangles_in(const PlacedMesh& m, const DBox& box) {
    std::vector<std::uint32_t> out;
    for (std::size_t t = 0; t < m.triangle_bounds.size(); ++t)
        if (m.triangle_bounds[t].overlaps(box)) out.push_back(static_cast<std::uint32_t>(t));
    return out;
}

// A uniform grid over a box holding triangle indices: about one cell per triangle, cells
// shaped after the box. A triangle goes into every cell its bounds meet.
class TriangleGrid {
  public:
    TriangleGrid(const PlacedMesh& m, const std::vector<std::uint32_t>& tris, const DBox& box)
        : lo_(box.lo) {
        const glm::dvec3 extent = glm::max(box.hi - box.lo, glm::dvec3(0.0));
        const double longest = std::max({extent.x, extent.y, extent.z});
        const double target = std::max(1.0, std::cbrt(static_cast<double>(tris.size())));
        for (int a = 0; a < 3; ++a) {
            const double share = longest > 0.0 ? extent[a] / longest : 1.0;
            dims_[a] = std::clamp(static_cast<int>(std::ceil(target * share)), 1, 64);
            cell_[a] = extent[a] > 0.0 ? extent[a] / dims_[a] : 1.0;
        }
        cells_.resize(static_cast<std::size_t>(dims_.x) * dims_.y * dims_.z);
        for (const std::uint32_t t : tris) {
            const auto [c0, c1] = cell_range(m.triangle_bounds[t]);
            for (int z = c0.z; z <= c1.z; ++z)
                for (int y = c0.y; y <= c1.y; ++y)
                    for (int x = c0.x; x <= c1.x; ++x) cells_[index(x, y, z)].push_back(t);
        }
    }

    // Calls f(t) for each triangle in the cells `b` meets (a triangle may come more than once).
    template <class F>
    void for_each_near(const DBox& b, F&& f) const {
        const auto [c0, c1] = cell_range(b);
        for (int z = c0.z; z <= c1.z; ++z)
            for (int y = c0.y; y <= c1.y; ++y)
                for (int x = c0.x; x <= c1.x; ++x)
                    for (const std::uint32_t t : cells_[index(x, y, z)]) f(t);
    }

  private:
    std::pair<glm::ivec3, glm::ivec3> cell_range(const DBox& b) const {
        glm::ivec3 c0, c1;
        for (int a = 0; a < 3; ++a) {
            c0[a] = std::clamp(static_cast<int>(std::floor((b.lo[a] - lo_[a]) / cell_[a])), 0,
                               dims_[a] - 1);
            c1[a] = std::clamp(static_cast<int>(std::floor((b.hi[a] - lo_[a]) / cell_[a])), 0,
                               dims_[a] - 1);
        }
        return {c0, c1};
    }
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * dims_.y + y) * dims_.x + x;
    }

    glm::dvec3 lo_;
    glm::ivec3 dims_{1};
    glm::dvec3 cell_{1.0};
    std::vector<std::vector<std::uint32_t>> cells_;
};

bool share_vertex(const AdjacencyMesh& m, std::uint32_t s, std::uint32_t t) {
    const std::uint32_t* a = &m.triangles[3 * std::size_t{s}];
    const std::uint32_t* b = &m.triangles[3 * std::size_t{t}];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) return true;
    return false;
}

// Tests each triangle of `first` in `box` against the triangles of `second` near it;
// `same` is true for one mesh against itself.
std::vector<IntersectionSegment> crossings(const PlacedMesh& first, const PlacedMesh& second,
                                           const DBox& box, bool same) {
    std::vector<IntersectionSegment> out;
    const std::vector<std::uint32_t> from_first = triangles_in(first, box);
    const std::vector<std::uint32_t> from_second = same ? from_first : triangles_in(second, box);
    if (from_first.empty() || from_second.empty()) return out;
    const TriangleGrid grid(second, from_second, box);
    // Which triangle of `first` last tested each one of `second`: each pair once.
    std::vector<std::uint32_t> tested_by(second.triangle_bounds.size(), ~0u);
    for (const std::uint32_t s : from_first) {
        const DBox& sb = first.triangle_bounds[s];
        const Triangle3 ts = triangle(first, s);
        grid.for_each_near(sb, [&](std::uint32_t t) {
            if (tested_by[t] == s) return;
            tested_by[t] = s;
            if (same && (t <= s || share_vertex(*first.mesh, s, t))) return;
            if (!sb.overlaps(second.triangle_bounds[t])) return;
            if (const auto c = triangle_crossing(ts, triangle(second, t)))
                out.push_back({c->a, c->b, s, t});
        });
    }
    return out;
}

}  // namespace

PlacedMesh place_mesh(const AdjacencyMesh& mesh, const glm::dmat4& transform) {
    PlacedMesh p;
    p.mesh = &mesh;
    p.positions.reserve(mesh.positions.size());
    for (const glm::vec3& v : mesh.positions)
        p.positions.push_back(glm::dvec3(transform * glm::dvec4(glm::dvec3(v), 1.0)));
    const std::size_t tris = mesh.triangle_count();
    p.triangle_bounds.reserve(tris);
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t* v = &mesh.triangles[3 * t];
        p.triangle_bounds.push_back(
            box_of(p.positions[v[0]], p.positions[v[1]], p.positions[v[2]]));
        const DBox& b = p.triangle_bounds.back();
        p.bounds = t == 0 ? b : DBox{glm::min(p.bounds.lo, b.lo), glm::max(p.bounds.hi, b.hi)};
    }
    return p;
}

std::vector<IntersectionSegment> pair_intersections(const PlacedMesh& first,
                                                    const PlacedMesh& second) {
    if (!first.bounds.overlaps(second.bounds)) return {};
    return crossings(first, second, intersect_boxes(first.bounds, second.bounds), false);
}

std::vector<IntersectionSegment> self_intersections(const PlacedMesh& mesh) {
    if (mesh.bounds.empty()) return {};
    return crossings(mesh, mesh, mesh.bounds, true);
}

std::vector<SceneIntersection> scene_intersections(std::span<const PlacedMesh> meshes) {
    std::vector<SceneIntersection> out;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const auto fi = static_cast<std::uint32_t>(i);
        for (const IntersectionSegment& s : self_intersections(meshes[i]))
            out.push_back({s, fi, fi});
        for (std::size_t j = i + 1; j < meshes.size(); ++j) {
            if (!meshes[i].bounds.overlaps(meshes[j].bounds)) continue;
            for (const IntersectionSegment& s : pair_intersections(meshes[i], meshes[j]))
                out.push_back({s, fi, static_cast<std::uint32_t>(j)});
        }
    }
    return out;
}

}  // namespace bz::geo
