#include "render/gpu_scene/mesh_cache.h"

#include <algorithm>
#include <memory>

#include "geometry/derived/closure.h"
#include "geometry/derived/dihedral.h"
#include "geometry/derived/edge_list.h"
#include "geometry/derived/simplify.h"
#include "render/shader_interface.h"

namespace bz::render {

namespace {

void instance_attributes(gl::VertexArray& vao, const gl::Buffer& instances, bool with_color) {
    vao.bind_buffer(kVertexBufferInstances, instances, sizeof(InstanceData), 0, 1);
    for (GLuint col = 0; col < 4; ++col) {
        vao.float_attribute(
            kAttribModelView + col, kVertexBufferInstances, 4,
            static_cast<GLuint>(offsetof(InstanceData, model_view) + col * sizeof(glm::vec4)));
    }
    if (with_color) {
        vao.float_attribute(kAttribColor, kVertexBufferInstances, 4, offsetof(InstanceData, color));
        vao.float_attribute(kAttribParams, kVertexBufferInstances, 4,
                            offsetof(InstanceData, params));
    }
}

// The geometry shader's per-triangle material boundary bits; one zero word without any.
std::vector<std::uint32_t> material_edge_bits(const geo::AdjacencyMesh& mesh) {
    if (!mesh.has_material_edges()) return {0u};
    std::vector<std::uint32_t> bits(mesh.triangle_count(), 0u);
    for (std::size_t h = 0; h < mesh.material_edges.size(); ++h)
        if (mesh.material_edges[h]) bits[h / 3] |= 1u << (h % 3);
    return bits;
}

}  // namespace

const GpuMesh& MeshCache::get(const scene::MeshLibrary& library, scene::MeshId id, int lod) {
    if (id >= meshes_.size()) meshes_.resize(id + 1);
    Slot& slot = meshes_[id];
    const std::uint32_t version = library.version(id);
    if (!slot.full || slot.full->version != version) {
        slot = Slot{};
        slot.full = std::make_unique<GpuMesh>();
        upload(*slot.full, library.mesh(id));
        slot.full->version = version;
    }
    // A mesh uploaded before the compute line method (or the prefilter) was chosen gets its
    // edge list (and facing table) now.
    if (lacks_edges(*slot.full)) upload_edges(*slot.full, library.mesh(id));
    if (lod <= 0) return *slot.full;
    if (!slot.simplify_tried) {
        slot.simplify_tried = true;
        if (auto reduced = geo::simplify_line_mesh(library.mesh(id))) {
            slot.simplified = std::make_unique<GpuMesh>();
            upload(*slot.simplified, *reduced);
            slot.simplified->version = version;
        }
    }
    if (slot.simplified && lacks_edges(*slot.simplified)) {
        if (auto reduced = geo::simplify_line_mesh(library.mesh(id)))
            upload_edges(*slot.simplified, *reduced);
    }
    return slot.simplified ? *slot.simplified : *slot.full;
}

void MeshCache::set_edge_lists(bool on) {
    edge_lists_ = on;
}

void MeshCache::set_edge_facing_tables(bool on) {
    edge_facing_tables_ = on;
}

bool MeshCache::lacks_edges(const GpuMesh& gpu) const {
    return edge_lists_ && (!gpu.has_edge_list || (edge_facing_tables_ && !gpu.has_edge_facing));
}

void MeshCache::upload_edges(GpuMesh& gpu, const geo::AdjacencyMesh& mesh) {
    gpu.edge_clusters = geo::cluster_edges(mesh, geo::build_edge_list(mesh));
    std::vector<geo::MeshEdge>& edges = gpu.edge_clusters.edges;
    gpu.edge_list.set(std::span<const geo::MeshEdge>(edges), GL_STATIC_DRAW);
    gpu.edge_count = static_cast<GLuint>(edges.size());
    const std::vector<glm::vec4> normals = geo::face_normals(mesh);
    gpu.face_normals.set(std::span<const glm::vec4>(normals), GL_STATIC_DRAW);
    if (edge_facing_tables_) {
        gpu.edge_facing = build_edge_facing_table(mesh, gpu.edge_clusters, normals);
        gpu.has_edge_facing = true;
    }
    edges = {};
    gpu.has_edge_list = true;
}

void MeshCache::upload(GpuMesh& gpu, const geo::AdjacencyMesh& mesh) {
    ++uploads_;
    gpu.positions.set(std::span<const glm::vec3>(mesh.positions), GL_STATIC_DRAW);
    const std::vector<glm::vec3> normals = geo::vertex_normals(mesh);
    gpu.vertex_normals.set(std::span<const glm::vec3>(normals), GL_STATIC_DRAW);
    gpu.adjacency.set(std::span<const std::uint32_t>(mesh.adjacency), GL_STATIC_DRAW);
    // The pieces serve both the clusters and the whole mesh's closure: found once.
    const geo::Pieces pieces = geo::connected_pieces(mesh);
    geo::ClusteredTriangles clustered = geo::cluster_triangles(mesh, pieces);
    gpu.triangles.set(std::span<const std::uint32_t>(clustered.indices), GL_STATIC_DRAW);
    gpu.cluster_vertices.set(std::span<const std::uint32_t>(clustered.vertices), GL_STATIC_DRAW);
    gpu.cluster_corners.set(std::span<const std::uint32_t>(clustered.corners), GL_STATIC_DRAW);
    gpu.triangle_clusters = std::move(clustered.clusters);
    gpu.triangle_bounds = clustered.all;
    gpu.outward_closed = geo::is_outward_closed(pieces);
    gpu.has_closed_clusters =
        std::any_of(gpu.triangle_clusters.begin(), gpu.triangle_clusters.end(),
                    [](const geo::TriangleCluster& k) { return k.closed; });
    const std::vector<float> cosines = geo::edge_dihedral_cosines(mesh);
    gpu.edge_cosines.set(std::span<const float>(cosines), GL_STATIC_DRAW);
    const std::vector<std::uint32_t> material_bits = material_edge_bits(mesh);
    gpu.edge_materials.set(std::span<const std::uint32_t>(material_bits), GL_STATIC_DRAW);
    gpu.has_material_edges = mesh.has_material_edges();
    if (edge_lists_) upload_edges(gpu, mesh);
    gpu.adjacency_count = static_cast<GLsizei>(mesh.adjacency.size());
    gpu.triangle_index_count = static_cast<GLsizei>(mesh.triangles.size());

    gpu.lines_vao.bind_buffer(kVertexBufferPositions, gpu.positions, sizeof(glm::vec3));
    gpu.lines_vao.float_attribute(kAttribPosition, kVertexBufferPositions, 3, 0);
    instance_attributes(gpu.lines_vao, *instances_, true);
    gpu.lines_vao.element_buffer(gpu.adjacency);

    gpu.prepass_vao.bind_buffer(kVertexBufferPositions, gpu.positions, sizeof(glm::vec3));
    gpu.prepass_vao.float_attribute(kAttribPosition, kVertexBufferPositions, 3, 0);
    instance_attributes(gpu.prepass_vao, *instances_, false);
    gpu.prepass_vao.element_buffer(gpu.triangles);

    gpu.fill_vao.bind_buffer(kVertexBufferPositions, gpu.positions, sizeof(glm::vec3));
    gpu.fill_vao.float_attribute(kAttribPosition, kVertexBufferPositions, 3, 0);
    instance_attributes(gpu.fill_vao, *instances_, true);
    gpu.fill_vao.bind_buffer(kVertexBufferNormals, gpu.vertex_normals, sizeof(glm::vec3));
    gpu.fill_vao.float_attribute(kAttribNormal, kVertexBufferNormals, 3, 0);
    gpu.fill_vao.element_buffer(gpu.triangles);
}

}  // namespace bz::render
