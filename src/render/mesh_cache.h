#pragma once
// One GPU mesh per scene::MeshId, shared by all its instances: welded positions, the
// adjacency index buffer for the line pass and a plain triangle index buffer for the prepass.
// Both vertex arrays read per-instance data from one shared instance buffer (binding 1).
#include <vector>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "scene/mesh_library.h"

namespace bz::render {

// Per-instance data, 96 bytes: locations 1-4 model-view, 5 colour, 6 parameters.
struct InstanceData {
    glm::mat4 model_view;
    glm::vec4 color;
    glm::vec4 params;  // x: cos(crease angle)
};

struct GpuMesh {
    gl::Buffer positions;
    gl::Buffer adjacency;
    gl::Buffer triangles;
    gl::VertexArray lines_vao;
    gl::VertexArray prepass_vao;
    std::uint32_t version = 0;
    GLsizei adjacency_count = 0;
    GLsizei triangle_index_count = 0;
};

class MeshCache {
public:
    explicit MeshCache(const gl::Buffer& instances) : instances_(&instances) {}
    // Uploads on first use and when the library's version for `id` changed.
    const GpuMesh& get(const scene::MeshLibrary& library, scene::MeshId id);

private:
    void upload(GpuMesh& gpu, const geo::AdjacencyMesh& mesh);
    const gl::Buffer* instances_;
    std::vector<std::unique_ptr<GpuMesh>> meshes_;
};

}  // namespace bz::render
