#include "geometry/line_mesh/twins.h"

#include <deque>
#include <limits>
#include <memory>

#include "geometry/line_mesh/edge_groups.h"

namespace bz::geo::detail {
namespace {

constexpr std::uint32_t kNoPair = std::numeric_limits<std::uint32_t>::max();

enum class FaceState : std::uint8_t { settled, pending, dropped };

// For every half-edge of a face in a twin pair, where its edge's group of faces lies.
struct GroupSpan {
    std::uint32_t start = 0;
    std::uint32_t count = 0;
};

class TwinResolver {
  public:
    TwinResolver(std::span<const std::uint32_t> tri, std::size_t vertex_count,
                 std::span<const TwinPair> pairs, std::vector<std::uint8_t>& dropped)
        : tri_(tri),
          pairs_(pairs),
          dropped_(dropped),
          state_(tri.size() / 3),
          pair_of_(tri.size() / 3, kNoPair),
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
        index_edges(vertex_count);
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

    void index_edges(std::size_t vertex_count) {
        groups_ = std::make_unique<EdgeGroups>(tri_, vertex_count);
        spans_.resize(tri_.size());
        groups_->for_each([&](const EdgeEntry* g, std::size_t n) {
            const auto start = static_cast<std::uint32_t>(g - groups_->data());
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint32_t h = half_edge(g[i]);
                if (state_[h / 3] == FaceState::pending) {
                    spans_[h] = {start, static_cast<std::uint32_t>(n)};
                }
            }
        });
    }

    // Calls fn(other_face, runs_same_direction) for every face other than `face` on each of
    // its edges.
    template <class Fn>
    void for_each_edge_face(std::uint32_t face, Fn&& fn) const {
        for (std::uint32_t h = 3 * face; h < 3 * face + 3; ++h) {
            const std::uint32_t to = tri_[h % 3 == 2 ? h - 2 : h + 1];
            const bool rev = tri_[h] > to;
            const EdgeEntry* g = groups_->data() + spans_[h].start;
            for (std::uint32_t i = 0; i < spans_[h].count; ++i) {
                const std::uint32_t f = half_edge(g[i]) / 3;
                if (f != face) fn(f, reversed(g[i]) == rev);
            }
        }
    }

    std::span<const std::uint32_t> tri_;
    std::span<const TwinPair> pairs_;
    std::vector<std::uint8_t>& dropped_;
    std::vector<FaceState> state_;
    std::vector<std::uint32_t> pair_of_;
    std::vector<std::uint8_t> decided_;
    std::vector<std::uint8_t> queued_;
    std::deque<std::uint32_t> queue_;
    std::unique_ptr<EdgeGroups> groups_;
    std::vector<GroupSpan> spans_;  // per half-edge, filled for faces in pairs
};

}  // namespace

std::size_t resolve_twins(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                          std::span<const TwinPair> pairs, std::vector<std::uint8_t>& dropped) {
    if (pairs.empty()) return 0;
    TwinResolver resolver(triangles, vertex_count, pairs, dropped);
    return resolver.run();
}

}  // namespace bz::geo::detail
