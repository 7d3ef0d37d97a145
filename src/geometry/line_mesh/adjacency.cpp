#include "geometry/line_mesh/adjacency.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geometry/line_mesh/edge_groups.h"

namespace bz::geo {
namespace {

using detail::EdgeEntry;
using detail::half_edge;
using detail::reversed;

// Corner of the same triangle that is not on half-edge h (edge e runs from corner e to e+1).
std::uint32_t far_corner(std::uint32_t h) {
    return h % 3 == 0 ? h + 2 : h - 1;
}

void check_input(std::span<const std::uint32_t> tri, std::size_t vertex_count) {
    if (tri.size() % 3 != 0) {
        throw std::invalid_argument("build_adjacency: index count " + std::to_string(tri.size()) +
                                    " is not a multiple of 3");
    }
    if (tri.size() / 3 > detail::kMaxEdgeGroupTriangles) {
        throw std::invalid_argument("build_adjacency: too many triangles");
    }
    const std::uint32_t top = tri.empty() ? 0 : *std::max_element(tri.begin(), tri.end());
    if (!tri.empty() && top >= vertex_count) {
        throw std::invalid_argument("build_adjacency: index " + std::to_string(top) +
                                    " out of range (" + std::to_string(vertex_count) +
                                    " vertices)");
    }
}

class Classifier {
  public:
    Classifier(std::span<const std::uint32_t> tri, Adjacency& out) : tri_(tri), out_(out) {}

    // Entries [g, g + n) are every face on one undirected edge, in half-edge order.
    void group(const EdgeEntry* g, std::size_t n) {
        if (n == 1) {
            ++out_.boundary_edges;  // kind and a_i == v_i are the defaults
        } else if (n == 2) {
            pair(g[0], g[1]);
        } else {
            ++out_.non_manifold_edges;
            out_.maybe_coincident_faces = true;
            for (std::size_t i = 0; i < n; ++i) {
                out_.edge_kinds[half_edge(g[i])] = EdgeKind::non_manifold;
            }
        }
    }

  private:
    void pair(EdgeEntry e0, EdgeEntry e1) {
        const std::uint32_t h0 = half_edge(e0), h1 = half_edge(e1);
        const std::uint32_t o0 = tri_[far_corner(h0)], o1 = tri_[far_corner(h1)];
        if (o0 == o1) out_.maybe_coincident_faces = true;
        if (reversed(e0) == reversed(e1)) {
            ++out_.inconsistent_edges;
            out_.edge_kinds[h0] = EdgeKind::inconsistent;
            out_.edge_kinds[h1] = EdgeKind::inconsistent;
            return;
        }
        out_.edge_kinds[h0] = EdgeKind::interior;
        out_.edge_kinds[h1] = EdgeKind::interior;
        out_.adjacency[2 * std::size_t{h0} + 1] = o1;
        out_.adjacency[2 * std::size_t{h1} + 1] = o0;
    }

    std::span<const std::uint32_t> tri_;
    Adjacency& out_;
};

}  // namespace

Adjacency build_adjacency(std::span<const std::uint32_t> triangles, std::size_t vertex_count) {
    check_input(triangles, vertex_count);
    Adjacency out;
    // Every edge starts as a boundary with a degenerate neighbour (a_i == v_i); grouping
    // overwrites the ones that have neighbours.
    out.adjacency.reserve(triangles.size() * 2);
    for (const std::uint32_t v : triangles) {
        out.adjacency.push_back(v);
        out.adjacency.push_back(v);
    }
    out.edge_kinds.assign(triangles.size(), EdgeKind::boundary);

    detail::EdgeGroups groups(triangles, vertex_count);
    Classifier classifier(triangles, out);
    groups.for_each([&](const EdgeEntry* g, std::size_t n) { classifier.group(g, n); });
    return out;
}

}  // namespace bz::geo
