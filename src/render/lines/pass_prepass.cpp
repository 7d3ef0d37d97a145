#include <vector>

#include "render/passes.h"

namespace bz::render {

gl::PipelineState depth_writing_state(const PassContext& ctx, bool color_write) {
    gl::PipelineState state;
    state.depth_test = ctx.settings.depth == DepthFormat::reversed_f32 ? gl::DepthTest::greater
                                                                       : gl::DepthTest::less;
    state.depth_write = true;
    state.color_write = color_write;
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    return state;
}

double depth_clear_value(const PassContext& ctx) {
    return ctx.settings.depth == DepthFormat::reversed_f32 ? 0.0 : 1.0;
}

namespace {

// A mesh with fewer triangle clusters than this is drawn whole, one instanced draw for all its
// instances: culling could save little, and a draw per instance costs more.
constexpr std::size_t kMinClustersToCull = 4;

bool culls_clusters(const PassContext& ctx, const GpuMesh& mesh, bool moves_vertices) {
    return !moves_vertices && ctx.settings.cluster_culling && ctx.triangle_draws != nullptr &&
           mesh.triangle_clusters.size() >= kMinClustersToCull;
}

}  // namespace

TriangleCullStats draw_batch_triangles(const PassContext& ctx, gl::PipelineState state,
                                       bool occluders_only, gl::VertexArray GpuMesh::*vao,
                                       bool moves_vertices) {
    // Every culled batch's draws go into one buffer, uploaded once.
    const ViewVolume view(ctx.cam.proj, ctx.cam.near, ctx.cam.far, 1.0);
    TriangleCullStats stats;
    std::vector<TriangleDraw> draws;
    struct Range {
        std::size_t first = 0, count = 0;
    };
    std::vector<Range> ranges(ctx.batches.batches.size());
    for (std::size_t i = 0; i < ctx.batches.batches.size(); ++i) {
        const Batch& b = ctx.batches.batches[i];
        if (occluders_only && !b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        if (!culls_clusters(ctx, mesh, moves_vertices)) continue;
        const bool skip_back_faces = b.eye_outside && mesh.outward_closed;
        ranges[i].first = draws.size();
        for (GLsizei k = 0; k < b.instance_count; ++k) {
            const GLuint inst = b.first_instance + static_cast<GLuint>(k);
            append_triangle_draws(mesh.triangle_clusters, mesh.triangle_bounds,
                                  ctx.batches.instances[inst].model_view, skip_back_faces, view,
                                  inst, draws, stats);
        }
        ranges[i].count = draws.size() - ranges[i].first;
    }
    if (!draws.empty()) {
        ctx.triangle_draws->set(std::span<const TriangleDraw>(draws), GL_STREAM_DRAW);
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, ctx.triangle_draws->id());
    }
    for (std::size_t i = 0; i < ctx.batches.batches.size(); ++i) {
        const Batch& b = ctx.batches.batches[i];
        if (occluders_only && !b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        const bool culled = culls_clusters(ctx, mesh, moves_vertices);
        if (culled && ranges[i].count == 0) continue;
        // Back faces of an outward-closed mesh seen from outside are hidden by its front faces.
        const bool cull = b.eye_outside && mesh.outward_closed;
        if (cull != state.cull_back) {
            state.cull_back = cull;
            gl::apply(state);
        }
        (mesh.*vao).bind();
        if (culled) {
            glMultiDrawElementsIndirect(
                GL_TRIANGLES, GL_UNSIGNED_INT,
                reinterpret_cast<const void*>(ranges[i].first * sizeof(TriangleDraw)),
                static_cast<GLsizei>(ranges[i].count), 0);
        } else {
            glDrawElementsInstancedBaseInstance(GL_TRIANGLES, mesh.triangle_index_count,
                                                GL_UNSIGNED_INT, nullptr, b.instance_count,
                                                b.first_instance);
        }
    }
    if (!draws.empty()) glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    return stats;
}

// Early-Z: fill the depth texture the spine test reads. Both faces are drawn so open,
// single-sided surfaces still hide what is behind them; back faces are culled only for
// outward-closed meshes seen from outside, whose back faces their front faces hide anyway.
void pass_prepass(const PassContext& ctx) {
    ctx.targets.depth_fbo.bind();
    const gl::PipelineState state = depth_writing_state(ctx, false);
    gl::apply(state);
    glClearDepth(depth_clear_value(ctx));
    glClear(GL_DEPTH_BUFFER_BIT);
    if (!ctx.occlusion) return;
    ctx.programs.prepass.use();
    ctx.programs.prepass.set("u_proj", ctx.cam.proj);
    const TriangleCullStats culled = draw_batch_triangles(ctx, state, true);
    if (ctx.stats) ctx.stats->triangle_culling = culled;
}

}  // namespace bz::render
