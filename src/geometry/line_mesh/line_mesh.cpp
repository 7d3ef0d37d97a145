#include "geometry/line_mesh/line_mesh.h"

#include <stdexcept>
#include <string>

#include "geometry/line_mesh/adjacency.h"
#include "geometry/line_mesh/clean.h"
#include "geometry/line_mesh/material_edges.h"
#include "geometry/line_mesh/weld.h"

namespace bz::geo {
namespace {

void fill_edge_counts(const Adjacency& adj, MeshReport& report) {
    report.boundary_edges = adj.boundary_edges;
    report.non_manifold_edges = adj.non_manifold_edges;
    report.inconsistent_edges = adj.inconsistent_edges;
}

}  // namespace

AdjacencyMesh build_line_mesh(const TriMesh& mesh, MeshReport* report) {
    MeshReport local;
    MeshReport& rep = report ? *report : local;
    rep = MeshReport{};
    rep.input_triangles = mesh.triangle_count();

    if (!mesh.face_materials.empty() && mesh.face_materials.size() != mesh.triangle_count()) {
        throw std::invalid_argument(
            "build_line_mesh: " + std::to_string(mesh.face_materials.size()) +
            " face materials for " + std::to_string(mesh.triangle_count()) + " triangles");
    }
    WeldedMesh welded = weld_positions(mesh);
    // Welding keeps every triangle in order; cleaning keeps the materials in step with it.
    std::vector<std::uint32_t> materials = mesh.face_materials;
    std::vector<std::uint32_t>* tags = materials.empty() ? nullptr : &materials;
    rep.degenerate_removed = remove_degenerate(welded.positions, welded.triangles, tags);
    if (rep.degenerate_removed > 0) compact_vertices(welded.positions, welded.triangles);

    Adjacency adj = build_adjacency(welded.triangles, welded.positions.size());
    // Adjacency proves the common case free of duplicates and twins; only look when it can't.
    if (adj.maybe_coincident_faces) {
        const CoincidentCounts cc =
            remove_coincident_faces(welded.triangles, welded.positions.size(), tags);
        rep.duplicates_removed = cc.duplicates;
        rep.twins_removed = cc.twins;
        if (cc.duplicates + cc.twins > 0) {
            compact_vertices(welded.positions, welded.triangles);
            adj = build_adjacency(welded.triangles, welded.positions.size());
        }
    }
    fill_edge_counts(adj, rep);
    rep.welded_vertices = welded.positions.size();

    AdjacencyMesh out;
    out.positions = std::move(welded.positions);
    out.triangles = std::move(welded.triangles);
    out.adjacency = std::move(adj.adjacency);
    out.edge_kinds = std::move(adj.edge_kinds);
    out.material_edges = find_material_edges(out.triangles, out.edge_kinds, materials);
    return out;
}

}  // namespace bz::geo
