#include "geometry/generated/subdivide.h"

#include <stdexcept>
#include <unordered_map>

#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {

namespace {

// One 1 -> 4 split. Midpoints are shared through an edge map so the result stays welded.
TriMesh split(const TriMesh& in) {
    TriMesh out;
    out.positions = in.positions;
    out.indices.reserve(in.indices.size() * 4);
    std::unordered_map<std::uint64_t, std::uint32_t> mid;
    mid.reserve(in.indices.size());
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
        const auto [it, added] =
            mid.try_emplace(key, static_cast<std::uint32_t>(out.positions.size()));
        if (added) out.positions.push_back((in.positions[a] + in.positions[b]) * 0.5f);
        return it->second;
    };
    for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3) {
        const std::uint32_t a = in.indices[t], b = in.indices[t + 1], c = in.indices[t + 2];
        const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    return out;
}

}  // namespace

AdjacencyMesh subdivide_flat(const AdjacencyMesh& mesh, int levels) {
    if (levels < 0 || levels > 6)
        throw std::invalid_argument("subdivide_flat: levels must be in [0, 6]");
    TriMesh m{mesh.positions, mesh.triangles, {}};
    for (int i = 0; i < levels; ++i) m = split(m);
    return build_line_mesh(m);
}

}  // namespace bz::geo
