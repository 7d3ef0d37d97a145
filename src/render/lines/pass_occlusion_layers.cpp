#include "geometry/reference/reference.h"
#include "render/passes.h"

namespace bz::render {

static_assert(kOcclusionLayers == geo::kMaxOcclusionLevel,
              "one peeled layer per occlusion level the reference tells apart");

namespace {

// Two surfaces closer than this (relative inverse depth) peel as one: coplanar pieces of one
// surface, and triangles meeting along a shared edge, are one surface to the eye.
constexpr float kPeelRelative = 1e-4f;

// vector-xray, which removes no hidden line: each surface facing the eye in front of a line
// halves its brightness, so what lies behind reads as behind.
constexpr float kXrayLevelDim = 0.5f;

}  // namespace

bool style_needs_occlusion_levels(const StyleDef& style) {
    return style.hidden.levels > 0 || !style.hidden_lines_removed;
}

// Depth peeling (Everitt 2001) of the occluders' surfaces facing the eye into
// kOcclusionLayers depth images: layer k holds the (k+1)-th nearest such surface at each pixel.
// Three geometry passes, paid only by the styles that draw hidden lines by level. Back faces are
// culled (the rasteriser's facing is the reference's, mirrored instances included), so the
// clusters wholly facing away are skipped too.
void pass_occlusion_layers(const PassContext& ctx) {
    gl::PipelineState state = depth_writing_state(ctx, false);
    for (int k = 0; k < kOcclusionLayers; ++k) {
        // The nearest layer needs no fragment stage (the depth test keeps the early-Z fast
        // path); the others discard what the layer before holds.
        const gl::Program& p = k == 0 ? ctx.programs.prepass : ctx.programs.occlusion_layer;
        ctx.targets.occlusion_layer_fbos[k].bind();
        gl::apply(state);
        glClearDepth(depth_clear_value(ctx));
        glClear(GL_DEPTH_BUFFER_BIT);
        p.use();
        p.set("u_proj", ctx.cam.proj);
        if (k == 0) {
            draw_batch_triangles(ctx, state, true, &GpuMesh::prepass_vao, false, true);
            continue;
        }
        p.set("u_proj_a", ctx.cam.proj_a);
        p.set("u_proj_inv_b", 1.0f / ctx.cam.proj_b);
        p.set("u_depth_zero_to_one", ctx.cam.zero_to_one ? 1 : 0);
        p.set("u_peel_rel", kPeelRelative);
        if (k > 0) ctx.targets.occlusion_layers[k - 1].bind(kTextureUnitPeelPrevious);
        draw_batch_triangles(ctx, state, true, &GpuMesh::prepass_vao, false, true);
    }
}

void bind_occlusion_layers(const PassContext& ctx) {
    for (int k = 0; k < kOcclusionLayers; ++k)
        ctx.targets.occlusion_layers[k].bind(kTextureUnitOcclusionLayer0 +
                                             static_cast<unsigned>(k));
}

bool dims_hidden_lines(const PassContext& ctx) {
    return !ctx.style.hidden_lines_removed && ctx.targets.occlusion_layers[0] &&
           frame_wrote(ctx, Resource::peel_layers);
}

void set_level_dim_uniforms(const PassContext& ctx, const gl::Program& program) {
    program.set("u_level_dim", kXrayLevelDim);
    bind_occlusion_layers(ctx);
}

}  // namespace bz::render
