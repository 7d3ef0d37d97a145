#include <cmath>

#include "render/clear_image.h"
#include "render/passes.h"

namespace bz::render {

// The image-space baseline's prepass: every object (occluders or not, the method cannot tell)
// into the depth target and a face-normal target.
void pass_outline_prepass(const PassContext& ctx) {
    ctx.targets.normals_fbo.bind();
    const gl::PipelineState state = depth_writing_state(ctx, true);
    gl::apply(state);
    clear_colour(ctx, ctx.targets.normals, glm::vec4(0.0f));
    glClearDepth(depth_clear_value(ctx));
    glClear(GL_DEPTH_BUFFER_BIT);
    const gl::Program& p = ctx.programs.outline_prepass;
    p.use();
    p.set("u_proj", ctx.cam.proj);
    // The same batches and back-face culling as pass_prepass, so the baseline is not charged
    // extra; all objects, since the method cannot tell occluders apart.
    draw_batch_triangles(ctx, state, false);
}

// Sobel over depth and normals, into the HDR lines target (or the mask in mask mode).
void pass_image_outline(const PassContext& ctx, bool mask_mode) {
    const gl::Program& p = mask_mode ? ctx.programs.image_outline_mask : ctx.programs.image_outline;
    (mask_mode ? ctx.targets.mask_fbo : ctx.targets.lines_fbo).bind();
    gl::apply(gl::PipelineState{});
    clear_colour(ctx, mask_mode ? ctx.targets.mask : ctx.targets.lines, glm::vec4(0.0f));
    p.use();
    p.set("u_proj_a", ctx.cam.proj_a);
    p.set("u_proj_b", ctx.cam.proj_b);
    p.set("u_depth_zero_to_one", ctx.cam.zero_to_one ? 1 : 0);
    p.set("u_depth_threshold", ctx.settings.outline_depth_threshold);
    const double half =
        static_cast<double>(ctx.settings.crease_angle_deg) * 3.14159265358979323846 / 360.0;
    p.set("u_normal_threshold", static_cast<float>(2.0 * std::sin(half)));
    p.set("u_color", glm::vec3(0.25f, 1.0f, 0.35f));
    ctx.targets.depth.bind(kTextureUnitDepth);
    ctx.targets.normals.bind(kTextureUnitNormals);
    ctx.empty_vao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace bz::render
