#include "render/gpu_scene/intersection_cache.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>

namespace bz::render {

// Named, not anonymous: IntersectionCache::State holds these types, and a unity build
// (CI) warns of a class whose members have internal linkage.
namespace intersection_cache_detail {

// What decides a placed mesh's triangles: the mesh, its version, the model matrix.
struct PlacementKey {
    scene::MeshId mesh = 0;
    std::uint32_t version = 0;
    std::array<double, 16> model{};
    bool operator==(const PlacementKey&) const = default;
};

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return h;
}

struct PlacementHash {
    std::size_t operator()(const PlacementKey& k) const {
        std::uint64_t h = mix(k.mesh, k.version);
        for (const double d : k.model) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &d, sizeof bits);
            h = mix(h, bits);
        }
        return static_cast<std::size_t>(h);
    }
};

struct PairKey {
    PlacementKey first, second;
    bool operator==(const PairKey&) const = default;
};

struct PairHash {
    std::size_t operator()(const PairKey& k) const {
        const PlacementHash h;
        return static_cast<std::size_t>(mix(h(k.first), h(k.second)));
    }
};

bool key_less(const PlacementKey& a, const PlacementKey& b) {
    if (a.mesh != b.mesh) return a.mesh < b.mesh;
    if (a.version != b.version) return a.version < b.version;
    return a.model < b.model;
}

// A cached segment: the two faces' unit normals with it.
struct CachedSegment {
    glm::dvec3 a{0.0}, b{0.0}, normal_first{0.0}, normal_second{0.0};
};

glm::dvec3 unit_normal(const geo::PlacedMesh& m, std::uint32_t t) {
    const std::uint32_t* v = &m.mesh->triangles[3 * std::size_t{t}];
    const glm::dvec3 n =
        glm::cross(m.positions[v[1]] - m.positions[v[0]], m.positions[v[2]] - m.positions[v[0]]);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

std::vector<CachedSegment> with_normals(const std::vector<geo::IntersectionSegment>& segs,
                                        const geo::PlacedMesh& first,
                                        const geo::PlacedMesh& second) {
    std::vector<CachedSegment> out;
    out.reserve(segs.size());
    for (const geo::IntersectionSegment& s : segs)
        out.push_back(
            {s.a, s.b, unit_normal(first, s.triangle_a), unit_normal(second, s.triangle_b)});
    return out;
}

geo::DBox world_bounds(const geo::Bounds& b, const glm::dmat4& model) {
    geo::DBox out{glm::dvec3(std::numeric_limits<double>::infinity()),
                  glm::dvec3(-std::numeric_limits<double>::infinity())};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                (i & 4) ? b.max.z : b.min.z);
        const glm::dvec3 w = glm::dvec3(model * glm::dvec4(corner, 1.0));
        out.lo = glm::min(out.lo, w);
        out.hi = glm::max(out.hi, w);
    }
    return out;
}

}  // namespace intersection_cache_detail

using namespace intersection_cache_detail;

struct IntersectionCache::State {
    struct Placement {
        geo::PlacedMesh placed;
        std::uint64_t used = 0;
    };
    struct Pair {
        std::vector<CachedSegment> segments;
        std::uint32_t first_id = 0;  // ids first_id, first_id + 1, ...
        std::uint64_t used = 0;
    };
    struct Own {  // a mesh's own crossings, in object space
        std::uint32_t version = 0;
        std::vector<CachedSegment> segments;
        std::uint32_t first_id = 0;
        std::uint64_t used = 0;
    };
    std::unordered_map<PlacementKey, Placement, PlacementHash> placements;
    std::unordered_map<PairKey, Pair, PairHash> pairs;
    std::unordered_map<scene::MeshId, Own> own;
    std::uint64_t frame = 0;
    std::uint32_t next_id = 0;

    const geo::PlacedMesh& placed(const PlacementKey& k, const geo::AdjacencyMesh& mesh,
                                  const glm::dmat4& model) {
        Placement& p = placements[k];
        if (p.used == 0) p.placed = geo::place_mesh(mesh, model);
        p.used = frame;
        return p.placed;
    }

    std::uint32_t ids(std::size_t n) {
        const std::uint32_t first = next_id;
        next_id += static_cast<std::uint32_t>(n);
        return first;
    }
};

IntersectionCache::IntersectionCache() : state_(std::make_unique<State>()) {}
IntersectionCache::~IntersectionCache() = default;
IntersectionCache::IntersectionCache(IntersectionCache&&) noexcept = default;
IntersectionCache& IntersectionCache::operator=(IntersectionCache&&) noexcept = default;

const std::vector<WorldIntersection>& IntersectionCache::update(
    const std::vector<scene::DrawItem>& items, const scene::MeshLibrary& meshes) {
    const auto t0 = std::chrono::steady_clock::now();
    State& s = *state_;
    ++s.frame;
    stats_ = {};
    segments_.clear();

    struct Item {
        std::uint32_t index;
        PlacementKey key;
        geo::DBox bounds;
    };
    std::vector<Item> taking_part;
    for (std::size_t i = 0; i < items.size(); ++i) {
        const scene::DrawItem& d = items[i];
        if (!d.occluder || d.mesh >= meshes.size()) continue;
        PlacementKey key{d.mesh, meshes.version(d.mesh), {}};
        std::memcpy(key.model.data(), &d.model[0][0], sizeof key.model);
        taking_part.push_back(
            {static_cast<std::uint32_t>(i), key, world_bounds(meshes.bounds(d.mesh), d.model)});
    }
    stats_.placements = taking_part.size();

    // A mesh's own crossings: once per mesh version, then moved with each item.
    for (const Item& it : taking_part) {
        const scene::DrawItem& d = items[it.index];
        State::Own& own = s.own[d.mesh];
        if (own.used == 0 || own.version != it.key.version) {
            const geo::PlacedMesh at_origin = geo::place_mesh(meshes.mesh(d.mesh), glm::dmat4(1.0));
            own.segments = with_normals(geo::self_intersections(at_origin), at_origin, at_origin);
            own.version = it.key.version;
            own.first_id = s.ids(own.segments.size());
            ++stats_.meshes_computed;
        }
        own.used = s.frame;
        if (own.segments.empty()) continue;
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(d.model)));
        auto moved = [&](const glm::dvec3& n) {
            const glm::dvec3 w = normal_matrix * n;
            const double len = glm::length(w);
            return len > 0.0 ? w / len : glm::dvec3(0.0);
        };
        for (std::size_t k = 0; k < own.segments.size(); ++k) {
            const CachedSegment& c = own.segments[k];
            segments_.push_back({glm::dvec3(d.model * glm::dvec4(c.a, 1.0)),
                                 glm::dvec3(d.model * glm::dvec4(c.b, 1.0)), moved(c.normal_first),
                                 moved(c.normal_second), it.index, it.index,
                                 own.first_id + static_cast<std::uint32_t>(k)});
        }
    }

    // Pairs: sweep along x over the items sorted by their bounds' low x.
    std::vector<std::size_t> order(taking_part.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return taking_part[a].bounds.lo.x < taking_part[b].bounds.lo.x;
    });
    for (std::size_t oi = 0; oi < order.size(); ++oi) {
        const Item& x = taking_part[order[oi]];
        for (std::size_t oj = oi + 1; oj < order.size(); ++oj) {
            const Item& y = taking_part[order[oj]];
            if (y.bounds.lo.x > x.bounds.hi.x) break;
            if (!x.bounds.overlaps(y.bounds) || x.key == y.key) continue;
            ++stats_.pairs;
            // One entry per unordered pair: the lesser key first.
            const bool swap = key_less(y.key, x.key);
            const Item& f = swap ? y : x;
            const Item& g = swap ? x : y;
            State::Pair& pair = s.pairs[PairKey{f.key, g.key}];
            if (pair.used == 0) {
                const scene::DrawItem& df = items[f.index];
                const scene::DrawItem& dg = items[g.index];
                const geo::PlacedMesh& pf = s.placed(f.key, meshes.mesh(df.mesh), df.model);
                const geo::PlacedMesh& pg = s.placed(g.key, meshes.mesh(dg.mesh), dg.model);
                pair.segments = with_normals(geo::pair_intersections(pf, pg), pf, pg);
                pair.first_id = s.ids(pair.segments.size());
                ++stats_.pairs_computed;
            } else {
                // Keep the placements of a pair that is still there.
                if (auto p = s.placements.find(f.key); p != s.placements.end())
                    p->second.used = s.frame;
                if (auto p = s.placements.find(g.key); p != s.placements.end())
                    p->second.used = s.frame;
            }
            pair.used = s.frame;
            for (std::size_t k = 0; k < pair.segments.size(); ++k) {
                const CachedSegment& c = pair.segments[k];
                segments_.push_back({c.a, c.b, c.normal_first, c.normal_second, f.index, g.index,
                                     pair.first_id + static_cast<std::uint32_t>(k)});
            }
        }
    }

    std::erase_if(s.pairs, [&](const auto& e) { return e.second.used != s.frame; });
    std::erase_if(s.placements, [&](const auto& e) { return e.second.used != s.frame; });
    std::erase_if(s.own, [&](const auto& e) { return e.second.used != s.frame; });
    stats_.segments = segments_.size();
    stats_.update_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return segments_;
}

}  // namespace bz::render
