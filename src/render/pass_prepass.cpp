#include "render/passes.h"

namespace bz::render {

// Early-Z: fill the depth texture the spine test reads. Both faces are drawn so open,
// single-sided surfaces still hide what is behind them; back faces are culled only for
// outward-closed meshes seen from outside, whose back faces their front faces hide anyway.
void pass_prepass(const PassContext& ctx) {
    const bool reversed = ctx.settings.depth == DepthFormat::reversed_f32;
    ctx.targets.depth_fbo.bind();
    gl::PipelineState state;
    state.depth_test = reversed ? gl::DepthTest::greater : gl::DepthTest::less;
    state.depth_write = true;
    state.color_write = false;
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    gl::apply(state);
    glClearDepth(reversed ? 0.0 : 1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (!ctx.occlusion) return;
    ctx.programs.prepass.use();
    ctx.programs.prepass.set("u_proj", ctx.cam.proj);
    for (const Batch& b : ctx.batches.batches) {
        if (!b.occluder) continue;
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        const bool cull = b.eye_outside && mesh.outward_closed;
        if (cull != state.cull_back) {
            state.cull_back = cull;
            gl::apply(state);
        }
        mesh.prepass_vao.bind();
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, mesh.triangle_index_count, GL_UNSIGNED_INT,
                                            nullptr, b.instance_count, b.first_instance);
    }
}

}  // namespace bz::render
