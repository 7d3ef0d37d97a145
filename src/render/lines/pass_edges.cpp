#include <algorithm>

#include "render/passes.h"

namespace bz::render {

namespace {

// The edge buffer is sized for every edge of the frame when that is small, else for this many
// and grown when a frame appends more (EdgeStorage::keep_count).
constexpr std::size_t kInitialRecords = std::size_t{1} << 16;
constexpr GLuint kGroupSize = 64;     // local_size_x of edges.comp
constexpr GLuint kMaxGroups = 65535;  // the smallest GL_MAX_COMPUTE_WORK_GROUP_COUNT allowed

}  // namespace

// Edge extraction for LineMethod::compute: one dispatch per batch, one invocation per mesh
// edge and instance (edges.comp), appending the visible feature edges to the edge buffer.
void pass_edges(const PassContext& ctx) {
    std::size_t worst = 0;
    for (const Batch& b : ctx.batches.batches) {
        worst +=
            static_cast<std::size_t>(ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod).edge_count) *
            static_cast<std::size_t>(b.instance_count);
    }
    // A previous frame that overflowed asks for more; a frame that cannot overflow gets it all.
    const EdgeDrawCommand previous = ctx.edges.previous();
    ctx.edges.reserve(std::min(
        worst,
        std::max(kInitialRecords, std::size_t{previous.vertex_count / kVerticesPerEdge} + 1024)));
    const bool samples = wants_spine_samples(ctx);
    if (samples)
        ctx.edges.reserve_samples(std::size_t{previous.samples_used} + previous.samples_used / 4);
    ctx.edges.reset();

    const gl::Program& program = ctx.programs.edges;
    program.use();
    program.set("u_proj", ctx.cam.proj);
    program.set("u_viewport", glm::vec2(static_cast<float>(ctx.targets.width),
                                        static_cast<float>(ctx.targets.height)));
    program.set("u_near", ctx.cam.near);
    program.set("u_far", ctx.cam.far);
    program.set("u_capacity", ctx.edges.capacity());
    program.set("u_sample_capacity", samples ? ctx.edges.sample_capacity() : 0u);
    // A fragment in the viewport lies within its beam's half-width of its spine point: cover that.
    program.set("u_sample_margin", 16.0f);
    program.set("u_sample_spacing", ctx.settings.spine_sample_spacing_px);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, ctx.instances.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeRecordsBinding, ctx.edges.records().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCommandBinding, ctx.edges.command().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSpineSpansBinding, ctx.edges.spans().id());
    for (const Batch& b : ctx.batches.batches) {
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        if (mesh.edge_count == 0) continue;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeListBinding, mesh.edge_list.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgePositionsBinding, mesh.positions.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexNormalsBinding, mesh.vertex_normals.id());
        program.set("u_skip_back_faces",
                    (ctx.occlusion && b.eye_outside && mesh.outward_closed) ? 1 : 0);
        program.set("u_mesh_id", static_cast<unsigned>(b.mesh));
        // Chunks keep both work-group counts within the limit every implementation allows.
        const GLuint per_x = kGroupSize * kMaxGroups;
        for (GLuint edge0 = 0; edge0 < mesh.edge_count; edge0 += per_x) {
            const GLuint edges = std::min(per_x, mesh.edge_count - edge0);
            program.set("u_edge_base", edge0);
            program.set("u_edge_count", mesh.edge_count);
            for (GLuint inst0 = 0; inst0 < static_cast<GLuint>(b.instance_count);
                 inst0 += kMaxGroups) {
                const GLuint instances =
                    std::min(kMaxGroups, static_cast<GLuint>(b.instance_count) - inst0);
                program.set("u_first_instance", b.first_instance + inst0);
                glDispatchCompute((edges + kGroupSize - 1) / kGroupSize, instances, 1);
            }
        }
    }
    // The quad pass reads the records in its vertex shader and the count as its draw command.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

}  // namespace bz::render
