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

void draw_batch_triangles(const PassContext& ctx, gl::PipelineState state, bool occluders_only,
                          gl::VertexArray GpuMesh::*vao) {
    for (const Batch& b : ctx.batches.batches) {
        if (occluders_only && !b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        // Back faces of an outward-closed mesh seen from outside are hidden by its front faces.
        const bool cull = b.eye_outside && mesh.outward_closed;
        if (cull != state.cull_back) {
            state.cull_back = cull;
            gl::apply(state);
        }
        (mesh.*vao).bind();
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, mesh.triangle_index_count,
                                            GL_UNSIGNED_INT, nullptr, b.instance_count,
                                            b.first_instance);
    }
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
    draw_batch_triangles(ctx, state, true);
}

}  // namespace bz::render
