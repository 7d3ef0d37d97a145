#include "geometry/adjacency.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>

namespace bz::geo {
namespace {

// One triangle edge, filed under its lower vertex. High 32 bits: the higher vertex. Low 32 bits:
// (half-edge index << 1) | reversed, where reversed means the edge runs from the higher vertex
// to the lower. Sorting a bucket of these groups it by edge, then by half-edge: deterministic.
using EdgeEntry = std::uint64_t;

constexpr std::size_t kMaxTriangles = ((std::size_t{1} << 31) - 1) / 3;

std::uint32_t other_vertex(EdgeEntry e) {
    return static_cast<std::uint32_t>(e >> 32);
}
std::uint32_t half_edge(EdgeEntry e) {
    return static_cast<std::uint32_t>(e) >> 1;
}
bool reversed(EdgeEntry e) {
    return (e & 1u) != 0;
}

// Corner of the same triangle that is not on half-edge h (edge e runs from corner e to e+1).
std::uint32_t far_corner(std::uint32_t h) {
    return h % 3 == 0 ? h + 2 : h - 1;
}

void check_input(std::span<const std::uint32_t> tri, std::size_t vertex_count) {
    if (tri.size() % 3 != 0) {
        throw std::invalid_argument("build_adjacency: index count " + std::to_string(tri.size()) +
                                    " is not a multiple of 3");
    }
    if (tri.size() / 3 > kMaxTriangles) {
        throw std::invalid_argument("build_adjacency: too many triangles");
    }
    const std::uint32_t top = tri.empty() ? 0 : *std::max_element(tri.begin(), tri.end());
    if (!tri.empty() && top >= vertex_count) {
        throw std::invalid_argument("build_adjacency: index " + std::to_string(top) +
                                    " out of range (" + std::to_string(vertex_count) +
                                    " vertices)");
    }
}

// Counting sort of all half-edges by lower vertex. On return ends[v] is one past the last entry
// of vertex v's bucket, which starts at ends[v - 1] (or 0).
// Scratch that every slot of is written before it is read: left uninitialised.
using EdgeEntries = std::unique_ptr<EdgeEntry[]>;

EdgeEntries bucket_edges(std::span<const std::uint32_t> tri, std::vector<std::uint32_t>& ends) {
    for (std::size_t h = 0; h < tri.size(); h += 3) {
        const std::uint32_t a = tri[h], b = tri[h + 1], c = tri[h + 2];
        ++ends[std::min(a, b)];
        ++ends[std::min(b, c)];
        ++ends[std::min(c, a)];
    }
    std::uint32_t sum = 0;
    for (auto& e : ends) {
        const std::uint32_t n = e;
        e = sum;
        sum += n;
    }
    EdgeEntries entries(new EdgeEntry[tri.size()]);
    auto file = [&](std::uint32_t from, std::uint32_t to, std::size_t h) {
        const bool rev = from > to;
        const std::uint32_t lo = rev ? to : from, hi = rev ? from : to;
        const auto code = static_cast<std::uint32_t>(h << 1) | (rev ? 1u : 0u);
        entries[ends[lo]++] = (EdgeEntry{hi} << 32) | code;
    };
    for (std::size_t h = 0; h < tri.size(); h += 3) {
        const std::uint32_t a = tri[h], b = tri[h + 1], c = tri[h + 2];
        file(a, b, h);
        file(b, c, h + 1);
        file(c, a, h + 2);
    }
    return entries;
}

void sort_bucket(EdgeEntry* first, EdgeEntry* last) {
    if (last - first > 16) {
        std::sort(first, last);
        return;
    }
    for (EdgeEntry* i = first + 1; i < last; ++i) {
        const EdgeEntry v = *i;
        EdgeEntry* j = i;
        for (; j > first && *(j - 1) > v; --j) *j = *(j - 1);
        *j = v;
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

void classify_bucket(EdgeEntry* first, EdgeEntry* last, Classifier& classifier) {
    sort_bucket(first, last);
    while (first < last) {
        const std::uint32_t other = other_vertex(*first);
        EdgeEntry* end = first + 1;
        while (end < last && other_vertex(*end) == other) ++end;
        classifier.group(first, static_cast<std::size_t>(end - first));
        first = end;
    }
}

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

    std::vector<std::uint32_t> ends(vertex_count, 0);
    const EdgeEntries entries = bucket_edges(triangles, ends);
    Classifier classifier(triangles, out);
    std::uint32_t begin = 0;
    for (std::size_t v = 0; v < vertex_count; ++v) {
        classify_bucket(entries.get() + begin, entries.get() + ends[v], classifier);
        begin = ends[v];
    }
    return out;
}

}  // namespace bz::geo
