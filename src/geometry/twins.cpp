#include "geometry/twins.h"

#include <deque>
#include <limits>

namespace bz::geo::detail {
namespace {

constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();

enum class FaceState : std::uint8_t { settled, pending, dropped };

// Faces around each vertex (compressed rows), over the faces still present.
struct VertexFaces {
    std::vector<std::uint32_t> start;  // vertex_count + 1
    std::vector<std::uint32_t> faces;

    std::span<const std::uint32_t> of(std::uint32_t v) const {
        return {faces.data() + start[v], faces.data() + start[v + 1]};
    }
};

VertexFaces index_faces(std::span<const std::uint32_t> tri, std::size_t vertex_count,
                        const std::vector<FaceState>& state) {
    VertexFaces vf;
    vf.start.assign(vertex_count + 1, 0);
    for (std::size_t i = 0; i < tri.size(); ++i) {
        if (state[i / 3] != FaceState::dropped) ++vf.start[tri[i] + 1];
    }
    for (std::size_t v = 0; v < vertex_count; ++v) vf.start[v + 1] += vf.start[v];
    vf.faces.resize(vf.start[vertex_count]);
    std::vector<std::uint32_t> cursor(vf.start.begin(), vf.start.end() - 1);
    for (std::size_t i = 0; i < tri.size(); ++i) {
        if (state[i / 3] != FaceState::dropped) {
            vf.faces[cursor[tri[i]]++] = static_cast<std::uint32_t>(i / 3);
        }
    }
    return vf;
}

class TwinResolver {
  public:
    TwinResolver(std::span<const std::uint32_t> tri, std::size_t vertex_count,
                 std::span<const TwinPair> pairs, std::vector<std::uint8_t>& dropped)
        : tri_(tri),
          pairs_(pairs),
          dropped_(dropped),
          state_(tri.size() / 3),
          pair_of_(tri.size() / 3, kUnset),
          decided_(pairs.size(), 0),
          queued_(pairs.size(), 0) {
        for (std::size_t f = 0; f < state_.size(); ++f) {
            state_[f] = dropped[f] ? FaceState::dropped : FaceState::settled;
        }
        for (std::size_t p = 0; p < pairs.size(); ++p) {
            for (std::uint32_t f : {pairs[p].first, pairs[p].second}) {
                state_[f] = FaceState::pending;
                pair_of_[f] = static_cast<std::uint32_t>(p);
            }
        }
        around_ = index_faces(tri, vertex_count, state_);
    }

    std::size_t run() {
        for (std::size_t p = 0; p < pairs_.size(); ++p) enqueue(p);
        std::size_t next_forced = 0;
        for (;;) {
            drain_queue();
            while (next_forced < pairs_.size() && decided_[next_forced]) ++next_forced;
            if (next_forced == pairs_.size()) break;
            // Nothing settled votes on the rest: keep the first face of the first open pair.
            decide(next_forced, pairs_[next_forced].first);
        }
        return pairs_.size();
    }

  private:
    void enqueue(std::size_t p) {
        if (decided_[p] || queued_[p]) return;
        queued_[p] = 1;
        queue_.push_back(static_cast<std::uint32_t>(p));
    }

    void drain_queue() {
        while (!queue_.empty()) {
            const std::uint32_t p = queue_.front();
            queue_.pop_front();
            queued_[p] = 0;
            if (decided_[p]) continue;
            const int s = score(pairs_[p].first);
            if (s > 0) decide(p, pairs_[p].first);
            if (s < 0) decide(p, pairs_[p].second);
        }
    }

    void decide(std::size_t p, std::uint32_t keep) {
        const std::uint32_t lose = keep == pairs_[p].first ? pairs_[p].second : pairs_[p].first;
        decided_[p] = 1;
        state_[keep] = FaceState::settled;
        state_[lose] = FaceState::dropped;
        dropped_[lose] = 1;
        for_each_edge_face(keep, [&](std::uint32_t f, bool) {
            if (state_[f] == FaceState::pending) enqueue(pair_of_[f]);
        });
    }

    // Settled faces across the edges of `face` that wind the same way, minus those that wind
    // the other way.
    int score(std::uint32_t face) {
        int s = 0;
        for_each_edge_face(face, [&](std::uint32_t f, bool same_direction) {
            if (state_[f] == FaceState::settled) s += same_direction ? -1 : 1;
        });
        return s;
    }

    // Calls fn(other_face, runs_same_direction) for every face other than `face` on each of
    // its edges. Scans the shorter of the two endpoint lists so a high-valence hub stays cheap.
    template <class Fn>
    void for_each_edge_face(std::uint32_t face, Fn&& fn) const {
        for (std::uint32_t e = 0; e < 3; ++e) {
            const std::uint32_t u = tri_[3 * face + e], v = tri_[3 * face + (e + 1) % 3];
            const auto list_u = around_.of(u), list_v = around_.of(v);
            const bool scan_u = list_u.size() <= list_v.size();
            for (std::uint32_t f : scan_u ? list_u : list_v) {
                if (f == face) continue;
                const int dir = direction(f, u, v);
                if (dir != 0) fn(f, dir > 0);
            }
        }
    }

    // +1 if face f has edge u->v, -1 if it has v->u, 0 if it lacks the edge.
    int direction(std::uint32_t f, std::uint32_t u, std::uint32_t v) const {
        for (std::uint32_t k = 0; k < 3; ++k) {
            if (tri_[3 * f + k] != u) continue;
            if (tri_[3 * f + (k + 1) % 3] == v) return 1;
            if (tri_[3 * f + (k + 2) % 3] == v) return -1;
        }
        return 0;
    }

    std::span<const std::uint32_t> tri_;
    std::span<const TwinPair> pairs_;
    std::vector<std::uint8_t>& dropped_;
    std::vector<FaceState> state_;
    std::vector<std::uint32_t> pair_of_;
    std::vector<std::uint8_t> decided_;
    std::vector<std::uint8_t> queued_;
    std::deque<std::uint32_t> queue_;
    VertexFaces around_;
};

}  // namespace

std::size_t resolve_twins(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                          std::span<const TwinPair> pairs, std::vector<std::uint8_t>& dropped) {
    if (pairs.empty()) return 0;
    TwinResolver resolver(triangles, vertex_count, pairs, dropped);
    return resolver.run();
}

}  // namespace bz::geo::detail
