#include <cmath>

#include "render/beam/beam_uniforms.h"
#include "render/clear_image.h"
#include "render/gpu_scene/batches.h"
#include "render/passes.h"

namespace bz::render {

float spine_tolerance_abs(const PassContext& ctx) {
    const double inv_b = 1.0 / static_cast<double>(ctx.cam.proj_b);
    // Stored depth -> inverse depth is (ndc + a) * inv_b. A 24-bit buffer rounds ndc to steps
    // of 2^-23; allow four (rounding plus the float interpolation before it). Float depth's
    // step is relative and covered by plane_tolerance_rel, except for the rounding of the
    // constant a, which is an absolute error.
    const double step =
        ctx.settings.depth == DepthFormat::conventional_d24 ? std::ldexp(1.0, -21) : 0.0;
    return static_cast<float>((step + 1e-6 * std::abs(static_cast<double>(ctx.cam.proj_a))) *
                              std::abs(inv_b));
}

namespace {

// The spine test's tolerances: how far the prepass may sit from the exact plane of the edge's
// face, in inverse view depth.
void set_spine_tolerances(const gl::Program& p, const PassContext& ctx) {
    const auto& s = ctx.settings;
    p.set("u_tol_rel", s.plane_tolerance_rel);
    p.set("u_tol_abs", spine_tolerance_abs(ctx));
    p.set("u_tol_px", s.plane_tolerance_px);
    p.set("u_fallback_rel", s.depth_bias);
}

}  // namespace

void set_edge_projection_uniforms(const gl::Program& p, const PassContext& ctx) {
    p.set("u_proj", ctx.cam.proj);
    p.set("u_viewport",
          glm::vec2(static_cast<float>(ctx.targets.width), static_cast<float>(ctx.targets.height)));
    p.set("u_near", ctx.cam.near);
    p.set("u_far", ctx.cam.far);
}

void set_spine_test_uniforms(const gl::Program& p, const PassContext& ctx) {
    set_spine_tolerances(p, ctx);
    p.set("u_occlusion", ctx.occlusion ? 1 : 0);
    p.set("u_proj_a", ctx.cam.proj_a);
    p.set("u_proj_inv_b", 1.0f / ctx.cam.proj_b);
    p.set("u_depth_zero_to_one", ctx.cam.zero_to_one ? 1 : 0);
    // View ray through window position (x, y): ndc = pixel * 2 / size - 1, ray = ndc / P.
    const float w = static_cast<float>(ctx.targets.width),
                h = static_cast<float>(ctx.targets.height);
    const float px = ctx.cam.proj[0][0], py = ctx.cam.proj[1][1];
    p.set("u_ray", glm::vec4(2.0f / (w * px), 2.0f / (h * py), -1.0f / px, -1.0f / py));
    p.set("u_depth_max", glm::ivec2(ctx.targets.width - 1, ctx.targets.height - 1));
}

void set_line_uniforms(const gl::Program& p, const PassContext& ctx) {
    set_edge_projection_uniforms(p, ctx);
    set_spine_test_uniforms(p, ctx);
}

// The mask marks the pixels whose unit square the spine crosses: their centres lie within
// sqrt(2)/2 of the spine (sideways and past its ends), so a quad of half-width 0.75 holds them
// all. The beam fades to exactly zero at its half-width, so its quad is already as small as
// the beam.
constexpr float kMaskHalfWidth = 0.75f;

void bind_beam_tiles(const Targets& targets) {
    glBindImageTexture(kImageUnitBeamTiles, targets.beam_tiles.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_R8UI);
}

void begin_line_target(const PassContext& ctx, const gl::Program& program, bool mask_mode,
                       bool clear) {
    (mask_mode ? ctx.targets.mask_fbo : ctx.targets.lines_fbo).bind();
    gl::PipelineState state;
    state.blend = !mask_mode && ctx.settings.beam.blend == BeamBlend::additive ? gl::Blend::add
                                                                               : gl::Blend::max;
    state.depth_zero_to_one = ctx.cam.zero_to_one;
    gl::apply(state);
    if (clear) clear_colour(ctx, mask_mode ? ctx.targets.mask : ctx.targets.lines, glm::vec4(0.0f));
    if (!mask_mode) {
        // The beam's fragments mark the tiles they light, afresh each frame.
        Targets& t = ctx.targets;
        if (clear) glClearTexImage(t.beam_tiles.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
        bind_beam_tiles(t);
        program.set("u_skip_beam_tiles", ctx.dense_first_downsample ? 1 : 0);
    }
    if (!mask_mode && ctx.view_rows > 0 && ctx.view_rows < ctx.targets.height) {
        state.scissor_rows = ctx.view_rows;  // after the clear, which must cover every row
        state.scissor_width = ctx.targets.width;
        gl::apply(state);
    }
    program.use();
    set_line_uniforms(program, ctx);
    set_beam_uniforms(program, ctx.settings.beam, ctx.settings.line_half_width_px,
                      ctx.targets.height, ctx.seed, mask_mode);
    if (mask_mode)
        program.set("u_beam_width", glm::vec4(kMaskHalfWidth, kMaskHalfWidth, 0.0f, 1.0f));
    ctx.targets.depth.bind(kTextureUnitDepth);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding, ctx.instances.id());
}

// The feature-line pass of LineMethod::geometry_shader: the geometry shader finds and extrudes
// edges, the fragment shader runs the spine test against the prepass depth and shades the
// beam. GL_MAX blending keeps overlapping ends and crossings from getting brighter than a
// single line; additive blending (BeamBlend::additive, MAME's) lets them add, as on a tube.
void pass_lines(const PassContext& ctx, bool mask_mode) {
    const bool levels = !mask_mode && dims_hidden_lines(ctx);
    const gl::Program& program = mask_mode ? ctx.programs.mask
                                 : levels  ? ctx.programs.lines_dim
                                           : ctx.programs.lines;
    begin_line_target(ctx, program, mask_mode);
    if (levels) set_level_dim_uniforms(ctx, program);
    program.set("u_edges_to_test", 3);  // a uniform loop bound: keeps one copy of the emit code
    for (const Batch& b : ctx.batches.batches) {
        const GpuMesh& mesh = ctx.gpu_meshes.get(ctx.meshes, b.mesh, b.lod);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeCosinesBinding, mesh.edge_cosines.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kEdgeMaterialsBinding, mesh.edge_materials.id());
        program.set("u_material_lines", material_lines_for(ctx.settings, b, mesh) ? 1 : 0);
        program.set("u_skip_back_faces",
                    (ctx.occlusion && b.eye_outside && mesh.outward_closed) ? 1 : 0);
        mesh.lines_vao.bind();
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES_ADJACENCY, mesh.adjacency_count,
                                            GL_UNSIGNED_INT, nullptr, b.instance_count,
                                            b.first_instance);
    }
}

}  // namespace bz::render
