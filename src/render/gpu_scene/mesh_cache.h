#pragma once
// One GPU mesh per scene::MeshId, shared by all its instances: welded positions and smooth
// vertex normals, the adjacency index buffer for the line pass and a plain triangle index
// buffer for the prepass and the fills.
// The vertex arrays read per-instance data from one shared instance buffer (the locations and
// binding points of render/shader_interface.h).
// Distance LOD: a mesh may also have a simplified GPU mesh (geo::simplify_line_mesh), built
// the first time a far instance asks for it.
#include <memory>
#include <vector>

#include "geometry/derived/edge_clusters.h"
#include "geometry/derived/triangle_clusters.h"
#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "render/lines/edge_prefilter.h"
#include "scene/mesh_library.h"

namespace bz::render {

// Per-instance data, 96 bytes = kInstanceVec4s vec4 (render/shader_interface.h, which pins the
// layout with static_asserts and hands it to the shaders; shaders/instance_data.glsl reads it).
struct InstanceData {
    glm::mat4 model_view;
    glm::vec4 color;
    glm::vec4 params;  // x: cos(crease angle), y: this instance's index in the buffer,
                       // z: intensity (the beam's width follows it: shaders/beam/beam_width.glsl),
                       // w: 1 = smooth shading (filled styles)
};

struct GpuMesh {
    gl::Buffer positions;
    gl::Buffer vertex_normals;  // smooth vertex normals (geo::vertex_normals)
    // Styles with strokes and LineMethod::compute (MeshCache::set_edge_lists): the unique edge
    // list (geo::MeshEdge, binding kEdgeListBinding) the edge extraction reads, grouped into
    // clusters (geo::cluster_edges), and each triangle's object-space normal
    // (geo::face_normals, binding kFaceNormalsBinding) it tests facing with.
    gl::Buffer edge_list;
    gl::Buffer face_normals;
    GLuint edge_count = 0;
    // The clusters' bounds and crease keys, for culling on the CPU each frame
    // (render/lines/edge_culling.h); `edges` is emptied once uploaded.
    geo::ClusteredEdges edge_clusters;
    // With the CPU edge prefilter (MeshCache::set_edge_facing_tables): what it tests per edge.
    EdgeFacingTable edge_facing;
    gl::Buffer adjacency;
    // The triangle list cluster by cluster (geo::cluster_triangles), for the prepass and the
    // fills, and the clusters' bounds, for culling them on the CPU each frame.
    gl::Buffer triangles;
    // Each cluster's distinct vertices and each triangle's corners into them
    // (geo::ClusteredTriangles::vertices, corners), for the compute prepass.
    gl::Buffer cluster_vertices;
    gl::Buffer cluster_corners;
    std::vector<geo::TriangleCluster> triangle_clusters;
    geo::ClusterBounds triangle_bounds;  // a sphere around them all
    gl::Buffer edge_cosines;  // 3 per triangle, read by the geometry shader (kEdgeCosinesBinding)
    // Per triangle, bit e set where edge e is a material boundary (geo::AdjacencyMesh::
    // material_edges), read by the geometry shader (kEdgeMaterialsBinding); one zero word when
    // the mesh has none (has_material_edges false: the shader is told not to read it).
    gl::Buffer edge_materials;
    bool has_material_edges = false;
    bool has_edge_list = false;    // edge_list is filled (uploaded on first use with edge lists on)
    bool has_edge_facing = false;  // edge_facing is built (it may be empty: a mesh without edges)
    gl::VertexArray lines_vao;
    gl::VertexArray prepass_vao;
    gl::VertexArray fill_vao;  // triangles with normals, colour and parameters
    std::uint32_t version = 0;
    bool outward_closed = false;       // geo::is_outward_closed: back faces hidden from outside
    bool has_closed_clusters = false;  // some triangle cluster is of closed pieces only
    GLsizei adjacency_count = 0;
    GLsizei triangle_index_count = 0;
    std::size_t triangle_count() const {
        return static_cast<std::size_t>(triangle_index_count) / 3;
    }
};

class MeshCache {
  public:
    explicit MeshCache(const gl::Buffer& instances) : instances_(&instances) {}
    // Uploads on first use and when the library's version for `id` changed. lod 1 is the
    // simplified mesh when the mesh has one, else the mesh itself.
    const GpuMesh& get(const scene::MeshLibrary& library, scene::MeshId id, int lod = 0);
    // Build each mesh's edge list too (the compute line method); meshes uploaded without one
    // get it on their next use (not counted as an upload).
    void set_edge_lists(bool on);
    // Build each edge list's facing table too (the CPU edge prefilter, lines/edge_prefilter.h).
    void set_edge_facing_tables(bool on);
    // GPU meshes uploaded so far (each model once, plus its simplified version if used).
    std::size_t uploads() const { return uploads_; }

  private:
    struct Slot {
        std::unique_ptr<GpuMesh> full;
        std::unique_ptr<GpuMesh> simplified;  // null: none built yet, or none possible
        bool simplify_tried = false;
    };
    void upload(GpuMesh& gpu, const geo::AdjacencyMesh& mesh);
    void upload_edges(GpuMesh& gpu, const geo::AdjacencyMesh& mesh);
    bool lacks_edges(const GpuMesh& gpu) const;
    const gl::Buffer* instances_;
    std::vector<Slot> meshes_;
    std::size_t uploads_ = 0;
    bool edge_lists_ = false;
    bool edge_facing_tables_ = false;
};

}  // namespace bz::render
