#include "render/clear_image.h"
#include "render/passes.h"

namespace bz::render {

namespace {

const gl::Program& fill_program(const PassContext& ctx) {
    switch (ctx.style.fill) {
        case FillPass::toon:
            return ctx.programs.fill_toon;
        case FillPass::pop_art:
            return ctx.programs.fill_pop_art;
        case FillPass::paper:
        case FillPass::none:
            break;
    }
    return ctx.programs.fill_paper;
}

}  // namespace

// Paper tone, then every object filled in the style's look, writing the depth texture the
// strokes' spine test reads (this pass takes the prepass's place). Every object is filled,
// debris too: on paper anything solid hides what is behind it.
void pass_fill(const PassContext& ctx) {
    // In filled styles the lines target holds only the HUD; start it empty.
    ctx.targets.lines_fbo.bind();
    clear_colour(ctx, ctx.targets.lines, glm::vec4(0.0f));
    // The HUD marks the screen tiles it lights there (beam_tiles.glsl); the ink composite
    // shades only those and the halo's reach around them (pass_ink_composite.cpp).
    glClearTexImage(ctx.targets.beam_tiles.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);

    ctx.targets.canvas_depth_fbo.bind();
    const gl::PipelineState state = depth_writing_state(ctx, true);
    gl::apply(state);
    const glm::vec3 paper = ctx.style.background;
    clear_colour(ctx, ctx.targets.canvas, glm::vec4(paper, 1.0f));
    glClearDepth(depth_clear_value(ctx));
    glClear(GL_DEPTH_BUFFER_BIT);
    const gl::Program& p = fill_program(ctx);
    p.use();
    p.set("u_proj", ctx.cam.proj);
    p.set("u_light_dir", glm::normalize(ctx.style.light_dir));
    p.set("u_bands", ctx.style.toon_bands);
    p.set("u_cell_px", ctx.style.halftone_cell_px);
    p.set("u_paper", paper);
    p.set("u_tint", ctx.style.paper_tint);
    draw_batch_triangles(ctx, state, false, &GpuMesh::fill_vao);
}

// The halo's depth mask (Loviscach): the occluders again, shrunk along their vertex normals, so
// a stroke quad that reaches inside the silhouette stays in front of its own object.
void pass_shrunk_depth(const PassContext& ctx) {
    ctx.targets.shrunk_fbo.bind();
    const gl::PipelineState state = depth_writing_state(ctx, false);
    gl::apply(state);
    glClearDepth(depth_clear_value(ctx));
    glClear(GL_DEPTH_BUFFER_BIT);
    const gl::Program& p = ctx.programs.shrunk_depth;
    p.use();
    p.set("u_proj", ctx.cam.proj);
    // Pixels to view-space distance per unit of depth: 2 / (height * P[1][1]).
    p.set("u_shrink", ctx.style.halo.shrink_px * 2.0f /
                          (static_cast<float>(ctx.targets.height) * ctx.cam.proj[1][1]));
    // Shrunk vertices leave the clusters' bounds, and a shrunk face may turn: no cluster culling.
    draw_batch_triangles(ctx, state, true, &GpuMesh::fill_vao, true);
}

}  // namespace bz::render
