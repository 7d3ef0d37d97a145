#include "geometry/line_mesh/edge_groups.h"

#include <algorithm>

namespace bz::geo::detail {

EdgeGroups::EdgeGroups(std::span<const std::uint32_t> tri, std::size_t vertex_count)
    : entries_(new EdgeEntry[tri.size()]), ends_(vertex_count, 0) {
    for (std::size_t h = 0; h < tri.size(); h += 3) {
        const std::uint32_t a = tri[h], b = tri[h + 1], c = tri[h + 2];
        ++ends_[std::min(a, b)];
        ++ends_[std::min(b, c)];
        ++ends_[std::min(c, a)];
    }
    std::uint32_t sum = 0;
    for (auto& e : ends_) {
        const std::uint32_t n = e;
        e = sum;
        sum += n;
    }
    // Filing advances ends_[v] from the bucket's start to its end.
    auto file = [&](std::uint32_t from, std::uint32_t to, std::size_t h) {
        const bool rev = from > to;
        const std::uint32_t lo = rev ? to : from, hi = rev ? from : to;
        const auto code = static_cast<std::uint32_t>(h << 1) | (rev ? 1u : 0u);
        entries_[ends_[lo]++] = (EdgeEntry{hi} << 32) | code;
    };
    for (std::size_t h = 0; h < tri.size(); h += 3) {
        const std::uint32_t a = tri[h], b = tri[h + 1], c = tri[h + 2];
        file(a, b, h);
        file(b, c, h + 1);
        file(c, a, h + 2);
    }
}

// Buckets are tiny (about three edges per vertex in a closed mesh) except at hubs.
void EdgeGroups::sort_bucket(EdgeEntry* first, EdgeEntry* last) {
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

}  // namespace bz::geo::detail
