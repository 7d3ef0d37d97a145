#include "geometry/derived/closure.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace bz::geo {

namespace {

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];
        v = parent[v];
    }
    return v;
}

}  // namespace

Pieces connected_pieces(const AdjacencyMesh& mesh) {
    Pieces out;
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t i = 0; i + 2 < mesh.triangles.size(); i += 3) {
        const std::uint32_t a = find_root(parent, mesh.triangles[i]);
        parent[find_root(parent, mesh.triangles[i + 1])] = a;
        parent[find_root(parent, mesh.triangles[i + 2])] = a;
    }
    out.piece_of_vertex.resize(mesh.positions.size());
    std::vector<std::uint32_t> piece_of_root(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        std::uint32_t& piece = piece_of_root[find_root(parent, v)];
        if (piece == UINT32_MAX) {
            piece = static_cast<std::uint32_t>(out.pieces.size());
            out.pieces.emplace_back();
        }
        out.piece_of_vertex[v] = piece;
        Bounds& box = out.pieces[piece].box;
        box.min = glm::min(box.min, mesh.positions[v]);
        box.max = glm::max(box.max, mesh.positions[v]);
    }
    if (mesh.triangles.empty()) return out;
    // Every piece must be watertight and enclose a positive volume on its own: a model made of
    // many closed solids (a building's walls, slabs and rafters) may have one wound inside out.
    const glm::dvec3 origin(mesh.positions[mesh.triangles[0]]);
    std::vector<double> six_volume(out.pieces.size(), 0.0);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        Pieces::Piece& piece = out.pieces[out.piece_of_vertex[mesh.triangles[3 * t]]];
        ++piece.triangles;
        for (std::size_t e = 3 * t; e < 3 * t + 3; ++e)
            if (e >= mesh.edge_kinds.size() || mesh.edge_kinds[e] != EdgeKind::interior)
                piece.outward_closed = false;
        const glm::dvec3 a = glm::dvec3(mesh.positions[mesh.triangles[3 * t]]) - origin;
        const glm::dvec3 b = glm::dvec3(mesh.positions[mesh.triangles[3 * t + 1]]) - origin;
        const glm::dvec3 c = glm::dvec3(mesh.positions[mesh.triangles[3 * t + 2]]) - origin;
        six_volume[out.piece_of_vertex[mesh.triangles[3 * t]]] += glm::dot(a, glm::cross(b, c));
    }
    for (std::size_t p = 0; p < out.pieces.size(); ++p) {
        Pieces::Piece& piece = out.pieces[p];
        if (piece.triangles == 0 || !(six_volume[p] > 0.0)) piece.outward_closed = false;
    }
    return out;
}

bool is_outward_closed(const AdjacencyMesh& mesh) {
    if (mesh.triangles.empty()) return false;
    return is_outward_closed(connected_pieces(mesh));
}

bool is_outward_closed(const Pieces& pieces) {
    const bool any = std::any_of(pieces.pieces.begin(), pieces.pieces.end(),
                                 [](const Pieces::Piece& p) { return p.triangles > 0; });
    return any &&
           std::all_of(pieces.pieces.begin(), pieces.pieces.end(),
                       [](const Pieces::Piece& p) { return p.triangles == 0 || p.outward_closed; });
}

}  // namespace bz::geo
