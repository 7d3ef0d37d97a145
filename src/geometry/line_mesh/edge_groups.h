#pragma once
// All faces on each undirected edge of a welded triangle list, found by a counting sort of the
// half-edges by their lower vertex. Shared by adjacency building and twin resolution.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace bz::geo::detail {

// One half-edge, filed under its lower vertex. High 32 bits: the higher vertex. Low 32 bits:
// (half-edge index << 1) | reversed, where reversed means it runs from the higher vertex to the
// lower. Sorting a bucket of these groups it by edge, then by half-edge: deterministic.
using EdgeEntry = std::uint64_t;

inline std::uint32_t other_vertex(EdgeEntry e) {
    return static_cast<std::uint32_t>(e >> 32);
}
inline std::uint32_t half_edge(EdgeEntry e) {
    return static_cast<std::uint32_t>(e) >> 1;
}
inline bool reversed(EdgeEntry e) {
    return (e & 1u) != 0;
}

// Largest triangle count whose half-edge codes fit in 32 bits.
inline constexpr std::size_t kMaxEdgeGroupTriangles = ((std::size_t{1} << 31) - 1) / 3;

class EdgeGroups {
  public:
    // Indices must be < vertex_count and at most kMaxEdgeGroupTriangles triangles.
    EdgeGroups(std::span<const std::uint32_t> triangles, std::size_t vertex_count);

    // Calls fn(first, count) once per undirected edge with the entries of every half-edge on
    // it, in half-edge order. Edges come in order of (lower vertex, higher vertex).
    template <class Fn>
    void for_each(Fn&& fn) {
        std::uint32_t begin = 0;
        for (const std::uint32_t end : ends_) {
            EdgeEntry* first = entries_.get() + begin;
            EdgeEntry* const last = entries_.get() + end;
            sort_bucket(first, last);
            while (first < last) {
                EdgeEntry* group_end = first + 1;
                while (group_end < last && other_vertex(*group_end) == other_vertex(*first)) {
                    ++group_end;
                }
                fn(static_cast<const EdgeEntry*>(first),
                   static_cast<std::size_t>(group_end - first));
                first = group_end;
            }
            begin = end;
        }
    }

    // Base of the entries that for_each hands out, so callers can keep group offsets.
    const EdgeEntry* data() const { return entries_.get(); }

  private:
    static void sort_bucket(EdgeEntry* first, EdgeEntry* last);

    // Every slot is written before it is read, so it is left uninitialised.
    std::unique_ptr<EdgeEntry[]> entries_;
    std::vector<std::uint32_t> ends_;  // ends_[v]: one past the last entry of v's bucket
};

}  // namespace bz::geo::detail
