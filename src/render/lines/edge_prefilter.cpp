#include "render/lines/edge_prefilter.h"

#include <cmath>
#include <cstddef>

#include "geometry/derived/edge_list.h"

namespace bz::render {

namespace {

// edges.comp decides facing by the sign of dot(n, eye - a) when it exceeds 1e-4 |n| |eye - a|
// and falls back to a view-space test below; the same float expression here differs from
// the shader's by a few units in the last place, so twice that band leaves no doubt.
constexpr float kUnsure = 2e-4f;

// Whether the sign of s = dot(n, to_eye) is beyond doubt: |s| above the band (never for NaN).
bool sure(float s, const glm::vec3& n, float to_eye_squared) {
    return s * s > kUnsure * kUnsure * glm::dot(n, n) * to_eye_squared;
}

}  // namespace

EdgeFacingTable build_edge_facing_table(const geo::AdjacencyMesh& mesh,
                                        const geo::ClusteredEdges& clusters,
                                        const std::vector<glm::vec4>& face_normals) {
    EdgeFacingTable t;
    t.edges = clusters.edges.size();
    for (std::vector<float>& column : t.columns) column.reserve(t.edges + geo::kMaxClusterEdges);
    auto push = [&t](const glm::vec3& a, const glm::vec3& n_a, const glm::vec3& n_b, float key) {
        const float values[EdgeFacingTable::kColumns] = {a.x,   a.y,   a.z,   n_a.x, n_a.y,
                                                         n_a.z, n_b.x, n_b.y, n_b.z, key};
        for (int c = 0; c < EdgeFacingTable::kColumns; ++c) t.columns[c].push_back(values[c]);
    };
    for (std::size_t i = 0; i < clusters.edges.size(); ++i) {
        const geo::MeshEdge& e = clusters.edges[i];
        // edges.comp's test for face B (both its opposite vertex and its triangle)
        const bool has_b = e.opp_b != geo::kNoVertex && e.face_b != geo::kNoVertex;
        push(mesh.positions[e.a], glm::vec3(face_normals[e.face_a]),
             has_b ? glm::vec3(face_normals[e.face_b]) : glm::vec3(0.0f), clusters.crease_keys[i]);
    }
    // The padding, read by a block that runs past the list's end and never listed.
    for (std::uint32_t i = 0; i < geo::kMaxClusterEdges; ++i)
        push(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 2.0f);
    return t;
}

EdgeFacing EdgeFacingTable::at(std::size_t e) const {
    const auto& c = columns;
    return {{c[ax][e], c[ay][e], c[az][e]},
            {c[nax][e], c[nay][e], c[naz][e]},
            {c[nbx][e], c[nby][e], c[nbz][e]}};
}

bool uses_edge_prefilter(const RenderSettings& settings, bool software_rasteriser) {
    switch (settings.edge_prefilter) {
        case EdgePrefilter::gpu:
            return false;
        case EdgePrefilter::cpu:
            return true;
        case EdgePrefilter::automatic:
            break;
    }
    return software_rasteriser;
}

bool may_be_feature(const EdgeFacing& f, float crease_key, const glm::vec3& eye, float cos_crease) {
    // Creases, boundaries and material boundaries sort below any crease threshold they pass.
    // The same expressions as list_maybe_features's, so that the two agree on every edge.
    const glm::vec3 to_eye = eye - f.a;
    const float t = glm::dot(to_eye, to_eye);
    const float sa = glm::dot(f.n_a, to_eye);
    const float sb = glm::dot(f.n_b, to_eye);
    // No feature only where both faces surely face the same way (face B's zero normal when
    // there is none is never sure).
    const bool same_way = sure(sa, f.n_a, t) & sure(sb, f.n_b, t) & ((sa > 0.0f) == (sb > 0.0f));
    return (crease_key < cos_crease) | !same_way;
}

std::uint32_t list_maybe_features(const EdgeFacingTable& table, std::uint32_t first,
                                  std::uint32_t count, const glm::vec3& eye, float cos_crease,
                                  std::uint32_t* kept) {
    // may_be_feature, written so that the compiler runs it on SIMD vectors of edges: a fixed
    // trip count over a whole block (the table is padded for it), the columns side by side,
    // no branch; then the kept ones are gathered. On the 1.3M-triangle sphere's 29,652 tested
    // edges the edge-by-edge test took 15 ns an edge, this 11 with the table's lines coming
    // from memory and 3 from cache (docs/measurements/edge-clusters.md, session 18).
    constexpr std::uint32_t kBlock = geo::kMaxClusterEdges;
    const auto& c = table.columns;
    const float* ax = c[EdgeFacingTable::ax].data() + first;
    const float* ay = c[EdgeFacingTable::ay].data() + first;
    const float* az = c[EdgeFacingTable::az].data() + first;
    const float* nax = c[EdgeFacingTable::nax].data() + first;
    const float* nay = c[EdgeFacingTable::nay].data() + first;
    const float* naz = c[EdgeFacingTable::naz].data() + first;
    const float* nbx = c[EdgeFacingTable::nbx].data() + first;
    const float* nby = c[EdgeFacingTable::nby].data() + first;
    const float* nbz = c[EdgeFacingTable::nbz].data() + first;
    const float* key = c[EdgeFacingTable::crease_key].data() + first;
    constexpr float kBand = kUnsure * kUnsure;
    std::uint8_t maybe[kBlock];
    for (std::uint32_t i = 0; i < kBlock; ++i) {
        const float tx = eye.x - ax[i], ty = eye.y - ay[i], tz = eye.z - az[i];
        const float t = tx * tx + ty * ty + tz * tz;
        const float sa = nax[i] * tx + nay[i] * ty + naz[i] * tz;
        const float sb = nbx[i] * tx + nby[i] * ty + nbz[i] * tz;
        const float na = nax[i] * nax[i] + nay[i] * nay[i] + naz[i] * naz[i];
        const float nb = nbx[i] * nbx[i] + nby[i] * nby[i] + nbz[i] * nbz[i];
        const bool sure_a = sa * sa > kBand * na * t;
        const bool sure_b = sb * sb > kBand * nb * t;
        const bool same_way = sure_a & sure_b & ((sa > 0.0f) == (sb > 0.0f));
        maybe[i] = static_cast<std::uint8_t>((key[i] < cos_crease) | !same_way);
    }
    std::uint32_t n = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        kept[n] = first + i;
        n += maybe[i];
    }
    return n;
}

}  // namespace bz::render
