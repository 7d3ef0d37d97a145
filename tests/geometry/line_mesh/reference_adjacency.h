#pragma once
// A slow, obviously correct adjacency builder (std::map over undirected edges) that the tests
// compare the real one against.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo::test {

struct ReferenceAdjacency {
    std::vector<std::uint32_t> adjacency;
    std::vector<EdgeKind> kinds;
};

inline ReferenceAdjacency reference_adjacency(const std::vector<std::uint32_t>& tri) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> faces_on_edge;
    auto from = [&](std::size_t h) { return tri[h]; };
    auto to = [&](std::size_t h) { return tri[h % 3 == 2 ? h - 2 : h + 1]; };
    auto far = [&](std::size_t h) { return tri[h % 3 == 0 ? h + 2 : h - 1]; };
    for (std::size_t h = 0; h < tri.size(); ++h) {
        faces_on_edge[std::minmax(from(h), to(h))].push_back(h);
    }
    ReferenceAdjacency ref;
    ref.kinds.assign(tri.size(), EdgeKind::boundary);
    for (std::size_t h = 0; h < tri.size(); ++h) {
        ref.adjacency.push_back(from(h));
        ref.adjacency.push_back(from(h));
    }
    for (const auto& [edge, hs] : faces_on_edge) {
        if (hs.size() >= 3) {
            for (std::size_t h : hs) ref.kinds[h] = EdgeKind::non_manifold;
        } else if (hs.size() == 2) {
            const std::size_t h0 = hs[0], h1 = hs[1];
            if (from(h0) == from(h1)) {
                ref.kinds[h0] = ref.kinds[h1] = EdgeKind::inconsistent;
            } else {
                ref.kinds[h0] = ref.kinds[h1] = EdgeKind::interior;
                ref.adjacency[2 * h0 + 1] = far(h1);
                ref.adjacency[2 * h1 + 1] = far(h0);
            }
        }
    }
    return ref;
}

inline std::size_t count_kind(const std::vector<EdgeKind>& kinds, EdgeKind k) {
    std::size_t n = 0;
    for (EdgeKind e : kinds) n += e == k ? 1 : 0;
    return n;
}

}  // namespace bz::geo::test
