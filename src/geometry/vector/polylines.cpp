#include "geometry/vector/polylines.h"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace bz::geo {

namespace {

// Merges segment ends into nodes: an end within the tolerance of an earlier node of the same
// kind and instance becomes that node. A hash grid of tolerance-sized cells finds candidates.
class NodeTable {
  public:
    explicit NodeTable(double tolerance)
        : tolerance_(tolerance), cell_(std::max(tolerance, 1e-9)) {}

    std::uint32_t node(glm::dvec2 p, LineKind kind, std::uint32_t instance, std::uint8_t level) {
        instance = instance * 4u + level;  // level < 4: the key keeps the two apart
        const std::int64_t cx = cell_of(p.x), cy = cell_of(p.y);
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const auto it = cells_.find(Key{kind, instance, cx + dx, cy + dy});
                if (it == cells_.end()) continue;
                for (const std::uint32_t n : it->second) {
                    if (glm::length(positions_[n] - p) <= tolerance_) return n;
                }
            }
        }
        const auto n = static_cast<std::uint32_t>(positions_.size());
        positions_.push_back(p);
        cells_[Key{kind, instance, cx, cy}].push_back(n);
        return n;
    }
    const std::vector<glm::dvec2>& positions() const { return positions_; }

  private:
    struct Key {
        LineKind kind;
        std::uint32_t instance;
        std::int64_t x, y;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
            h ^= static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
            h ^= (static_cast<std::uint64_t>(k.instance) << 8 | static_cast<std::uint8_t>(k.kind)) *
                 0x165667B19E3779F9ull;
            return static_cast<std::size_t>(h ^ (h >> 29));
        }
    };
    std::int64_t cell_of(double v) const {
        return static_cast<std::int64_t>(std::floor(v / cell_));
    }

    double tolerance_;
    double cell_;
    std::vector<glm::dvec2> positions_;
    std::unordered_map<Key, std::vector<std::uint32_t>, KeyHash> cells_;
};

}  // namespace

std::vector<Polyline> chain_segments(std::span<const VisibleSegment> segments, double tolerance) {
    if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
        throw std::invalid_argument("chain_segments: the tolerance must be finite and >= 0");
    for (const VisibleSegment& s : segments) {
        if (!std::isfinite(s.a.x) || !std::isfinite(s.a.y) || !std::isfinite(s.b.x) ||
            !std::isfinite(s.b.y))
            throw std::invalid_argument("chain_segments: a segment end is not finite");
        if (s.level > kMaxOcclusionLevel)
            throw std::invalid_argument("chain_segments: an occlusion level above the cap");
    }
    NodeTable table(tolerance);
    const std::size_t n_seg = segments.size();
    std::vector<std::uint32_t> ends(2 * n_seg);  // the node at each segment end
    std::vector<Polyline> out;
    std::vector<char> used(n_seg, 0);
    for (std::size_t i = 0; i < n_seg; ++i) {
        const VisibleSegment& s = segments[i];
        ends[2 * i] = table.node(s.a, s.kind, s.instance, s.level);
        ends[2 * i + 1] = table.node(s.b, s.kind, s.instance, s.level);
    }
    const std::vector<glm::dvec2>& pos = table.positions();

    // Incidence lists (compressed): the segments at each node; a segment whose two ends merged
    // (shorter than the tolerance) is a polyline of its own and joins nothing.
    std::vector<std::uint32_t> first(pos.size() + 1, 0);
    for (std::size_t i = 0; i < n_seg; ++i) {
        if (ends[2 * i] == ends[2 * i + 1]) continue;
        ++first[ends[2 * i] + 1];
        ++first[ends[2 * i + 1] + 1];
    }
    for (std::size_t n = 0; n < pos.size(); ++n) first[n + 1] += first[n];
    std::vector<std::uint32_t> incident(first.back());
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t i = 0; i < n_seg; ++i) {
        if (ends[2 * i] == ends[2 * i + 1]) continue;
        incident[fill[ends[2 * i]]++] = static_cast<std::uint32_t>(i);
        incident[fill[ends[2 * i + 1]]++] = static_cast<std::uint32_t>(i);
    }
    auto degree = [&](std::uint32_t n) { return first[n + 1] - first[n]; };
    auto other_end = [&](std::uint32_t seg, std::uint32_t node) {
        return ends[2 * seg] == node ? ends[2 * seg + 1] : ends[2 * seg];
    };

    // Walks from `node` along `seg` through nodes where exactly two segments meet.
    auto walk = [&](std::uint32_t node, std::uint32_t seg) {
        Polyline line;
        line.kind = segments[seg].kind;
        line.instance = segments[seg].instance;
        line.level = segments[seg].level;
        line.points.push_back(pos[node]);
        for (;;) {
            used[seg] = 1;
            const std::uint32_t next = other_end(seg, node);
            line.points.push_back(pos[next]);
            if (degree(next) != 2) break;
            const std::uint32_t a = incident[first[next]], b = incident[first[next] + 1];
            const std::uint32_t t = a == seg ? b : a;
            if (used[t]) break;
            node = next;
            seg = t;
        }
        out.push_back(std::move(line));
    };

    for (std::size_t i = 0; i < n_seg; ++i) {
        if (ends[2 * i] != ends[2 * i + 1]) continue;
        used[i] = 1;
        out.push_back({{segments[i].a, segments[i].b},
                       segments[i].kind,
                       segments[i].instance,
                       segments[i].level,
                       segments[i].edge_offset_px});
    }
    // Open chains start at their ends (nodes where one, or three or more, segments meet) ...
    for (std::uint32_t n = 0; n < pos.size(); ++n) {
        if (degree(n) == 2) continue;
        for (std::uint32_t k = first[n]; k < first[n + 1]; ++k) {
            if (!used[incident[k]]) walk(n, incident[k]);
        }
    }
    // ... and what is left are closed loops.
    for (std::uint32_t i = 0; i < n_seg; ++i) {
        if (!used[i]) walk(ends[2 * i], i);
    }
    return out;
}

std::vector<Polyline> single_segments(std::span<const VisibleSegment> segments) {
    std::vector<Polyline> out;
    out.reserve(segments.size());
    for (const VisibleSegment& s : segments)
        out.push_back({{s.a, s.b}, s.kind, s.instance, s.level, s.edge_offset_px});
    return out;
}

}  // namespace bz::geo
