#include <bit>
#include <limits>

#include "geometry/line_mesh/clean.h"
#include "geometry/line_mesh/hash_mix.h"
#include "geometry/line_mesh/twins.h"

namespace bz::geo {
namespace {

constexpr std::uint32_t kUnsetIndex = std::numeric_limits<std::uint32_t>::max();

// The vertex set of a face in ascending order, plus which of the two windings it has.
struct FaceKey {
    std::uint32_t a = kUnsetIndex, b = kUnsetIndex, c = kUnsetIndex;
    bool operator==(const FaceKey&) const = default;
};

struct KeyedFace {
    FaceKey key;
    int winding;  // 0 or 1; faces with equal keys and equal winding are duplicates
};

KeyedFace key_face(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    // Rotate the lowest vertex to the front (rotation keeps the winding), then the order of the
    // other two is the winding.
    if (y < x && y < z) {
        std::swap(x, y);  // (y, z, x)
        std::swap(y, z);
    } else if (z < x && z < y) {
        std::swap(x, z);  // (z, x, y)
        std::swap(y, z);
    }
    if (y < z) return {{x, y, z}, 0};
    return {{x, z, y}, 1};
}

// For each distinct vertex set, the first face seen with each winding.
class FaceTable {
  public:
    explicit FaceTable(std::size_t faces)
        : slots_(detail::table_size_for(faces)), shift_(64 - std::countr_zero(slots_.size())) {}

    std::uint32_t* first_faces(const FaceKey& key) {
        const std::size_t mask = slots_.size() - 1;
        std::size_t i = detail::hash3(key.a, key.b, key.c) >> shift_;
        for (;; i = (i + 1) & mask) {
            Slot& s = slots_[i];
            if (s.key.a == kUnsetIndex) s.key = key;
            if (s.key == key) return s.first;
        }
    }

  private:
    struct Slot {
        FaceKey key;
        std::uint32_t first[2] = {kUnsetIndex, kUnsetIndex};
    };
    std::vector<Slot> slots_;
    int shift_;
};

void erase_dropped(std::vector<std::uint32_t>& tri, const std::vector<std::uint8_t>& dropped,
                   std::vector<std::uint32_t>* tags) {
    std::size_t kept = 0;
    for (std::size_t f = 0; f < dropped.size(); ++f) {
        if (dropped[f]) continue;
        if (tags) (*tags)[kept / 3] = (*tags)[f];
        for (std::size_t k = 0; k < 3; ++k) tri[kept + k] = tri[3 * f + k];
        kept += 3;
    }
    tri.resize(kept);
    if (tags) tags->resize(kept / 3);
}

}  // namespace

CoincidentCounts remove_coincident_faces(std::vector<std::uint32_t>& triangles,
                                         std::size_t vertex_count,
                                         std::vector<std::uint32_t>* face_tags) {
    const std::size_t faces = triangles.size() / 3;
    std::vector<std::uint8_t> dropped(faces, 0);
    std::vector<detail::TwinPair> pairs;
    CoincidentCounts counts;
    FaceTable table(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        const auto kf = key_face(triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]);
        std::uint32_t* first = table.first_faces(kf.key);
        if (first[kf.winding] != kUnsetIndex) {
            dropped[f] = 1;
            ++counts.duplicates;
            continue;
        }
        first[kf.winding] = static_cast<std::uint32_t>(f);
        const std::uint32_t reverse = first[1 - kf.winding];
        if (reverse != kUnsetIndex) pairs.push_back({reverse, static_cast<std::uint32_t>(f)});
    }
    counts.twins = detail::resolve_twins(triangles, vertex_count, pairs, dropped);
    if (counts.duplicates + counts.twins > 0) erase_dropped(triangles, dropped, face_tags);
    return counts;
}

}  // namespace bz::geo
