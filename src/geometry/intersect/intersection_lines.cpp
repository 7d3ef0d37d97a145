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

// The cells of `g` that `b` meets, as an inclusive range (empty when dims is zero).
std::pair<glm::ivec3, glm::ivec3> cell_range(const TriangleGridIndex& g, const DBox& b) {
    glm::ivec3 c0, c1;
    for (int a = 0; a < 3; ++a) {
        c0[a] = std::clamp(static_cast<int>(std::floor((b.lo[a] - g.lo[a]) / g.cell[a])), 0,
                           g.dims[a] - 1);
        c1[a] = std::clamp(static_cast<int>(std::floor((b.hi[a] - g.lo[a]) / g.cell[a])), 0,
                           g.dims[a] - 1);
    }
    return {c0, c1};
}

std::size_t cell_index(const TriangleGridIndex& g, int x, int y, int z) {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(g.dims.y) +
            static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(g.dims.x) +
           static_cast<std::size_t>(x);
}

TriangleGridIndex build_grid(const std::vector<DBox>& tris, const DBox& box) {
    TriangleGridIndex g;
    if (tris.empty() || box.empty()) return g;
    g.lo = box.lo;
    const glm::dvec3 extent = box.hi - box.lo;
    const double longest = std::max({extent.x, extent.y, extent.z});
    const double target = std::max(1.0, std::cbrt(static_cast<double>(tris.size())));
    for (int a = 0; a < 3; ++a) {
        const double share = longest > 0.0 ? extent[a] / longest : 1.0;
        g.dims[a] = std::clamp(static_cast<int>(std::ceil(target * share)), 1, 64);
        g.cell[a] = extent[a] > 0.0 ? extent[a] / g.dims[a] : 1.0;
    }
    const std::size_t cells = cell_index(g, 0, 0, g.dims.z);
    // Two passes (count, then fill): one allocation per placement.
    std::vector<std::uint32_t> count(cells + 1, 0);
    auto each_cell = [&](const DBox& b, auto&& f) {
        const auto [c0, c1] = cell_range(g, b);
        for (int z = c0.z; z <= c1.z; ++z)
            for (int y = c0.y; y <= c1.y; ++y)
                for (int x = c0.x; x <= c1.x; ++x) f(cell_index(g, x, y, z));
    };
    for (const DBox& b : tris) each_cell(b, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    g.first = count;
    g.items.resize(count[cells]);
    for (std::size_t t = 0; t < tris.size(); ++t)
        each_cell(tris[t],
                  [&](std::size_t c) { g.items[count[c]++] = static_cast<std::uint32_t>(t); });
    return g;
}

// Whether any triangle of `m` has bounds that meet `b`: stops at the first.
bool any_near(const PlacedMesh& m, const DBox& b) {
    const TriangleGridIndex& g = m.grid;
    if (g.dims.x == 0 || !m.bounds.overlaps(b)) return false;
    const auto [c0, c1] = cell_range(g, b);
    for (int z = c0.z; z <= c1.z; ++z)
        for (int y = c0.y; y <= c1.y; ++y)
            for (int x = c0.x; x <= c1.x; ++x) {
                const std::size_t c = cell_index(g, x, y, z);
                for (std::uint32_t k = g.first[c]; k < g.first[c + 1]; ++k)
                    if (m.triangle_bounds[g.items[k]].overlaps(b)) return true;
            }
    return false;
}

// Calls f(t) once for each triangle of `m` whose bounds meet `b`; `stamp` (one entry per
// triangle of m) and `mark` keep a triangle from coming twice.
template <class F>
void for_each_near(const PlacedMesh& m, const DBox& b, std::vector<std::uint32_t>& stamp,
                   std::uint32_t mark, F&& f) {
    const TriangleGridIndex& g = m.grid;
    if (g.dims.x == 0 || !m.bounds.overlaps(b)) return;
    const auto [c0, c1] = cell_range(g, b);
    for (int z = c0.z; z <= c1.z; ++z)
        for (int y = c0.y; y <= c1.y; ++y)
            for (int x = c0.x; x <= c1.x; ++x) {
                const std::size_t c = cell_index(g, x, y, z);
                for (std::uint32_t k = g.first[c]; k < g.first[c + 1]; ++k) {
                    const std::uint32_t t = g.items[k];
                    if (stamp[t] == mark) continue;
                    stamp[t] = mark;
                    if (m.triangle_bounds[t].overlaps(b)) f(t);
                }
            }
}

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
    // A mesh with no triangle in the box (a sparse mesh whose bounds merely hold the other)
    // ends the pair before any per-triangle work.
    if (!any_near(first, box) || !any_near(second, box)) return out;
    std::vector<std::uint32_t> stamp_first(first.triangle_bounds.size(), ~0u);
    std::vector<std::uint32_t> stamp_second(second.triangle_bounds.size(), ~0u);
    std::vector<std::uint32_t> from_first;
    for_each_near(first, box, stamp_first, 0u, [&](std::uint32_t s) { from_first.push_back(s); });
    for (const std::uint32_t s : from_first) {
        const DBox& sb = first.triangle_bounds[s];
        const Triangle3 ts = triangle(first, s);
        // Marks above 0 name the triangle of `first` asking: each pair once.
        for_each_near(second, sb, stamp_second, s + 1, [&](std::uint32_t t) {
            if (same && (t <= s || share_vertex(*first.mesh, s, t))) return;
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
    p.grid = build_grid(p.triangle_bounds, p.bounds);
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
