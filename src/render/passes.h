#pragma once
// The passes of one frame, one file each: prepass -> lines -> hud -> bloom -> composite.
// Each states the whole GL state it needs (gl::apply), so order is the only coupling.
#include <span>
#include <vector>

#include "gl/state.h"
#include "gl/vertex_array.h"
#include "render/batches.h"
#include "render/programs.h"
#include "render/targets.h"

namespace bz::render {

struct PassContext {
    const Programs& programs;
    Targets& targets;
    MeshCache& gpu_meshes;
    const scene::MeshLibrary& meshes;
    const FrameBatches& batches;
    const CameraMatrices& cam;
    const RenderSettings& settings;
    bool occlusion;                       // false in the arcade style
    const gl::VertexArray& empty_vao;     // for full-screen triangles
    const gl::Buffer& instances;          // the frame's InstanceData, also read as an SSBO
    std::uint32_t seed = 0;               // the frame's beam flicker seed (FrameList::seed)
    // Pixel rows from the bottom that the scene's lines may light (FrameList::view_top); the
    // rows above belong to the HUD band. 0: all of them.
    int view_rows = 0;
};

void pass_prepass(const PassContext& ctx);

// Shared by the depth-writing passes (pass_prepass.cpp): the state for the camera's depth
// convention, its clear value, and drawing every batch's triangles with the back-face culling
// that outward-closed meshes seen from outside allow.
gl::PipelineState depth_writing_state(const PassContext& ctx, bool color_write);
double depth_clear_value(const PassContext& ctx);
void draw_batch_triangles(const PassContext& ctx, gl::PipelineState state, bool occluders_only);
// mask_mode: draw the 1-pixel visible-spine mask into targets.mask instead of shaded lines.
void pass_lines(const PassContext& ctx, bool mask_mode);
void pass_hud(const PassContext& ctx, const gl::VertexArray& hud_vao, GLsizei vertex_count);
// Beam passes (the vector-monitor look, BeamSettings); each reads the image it is given, so a
// style may skip any of them. pass_phosphor returns the picture that bloom and composite read.
const gl::Texture2D& pass_phosphor(const PassContext& ctx, const gl::Texture2D& beam, double dt_seconds);
void pass_bloom(const PassContext& ctx, const gl::Texture2D& source);
// The weight of one level of the bloom chain (never zero: the chain divides by it).
float mip_weight(const std::vector<float>& weights, std::size_t level);
// `bloom`: false draws the picture without glow (bloom_out is not read).
void pass_composite(const PassContext& ctx, const gl::Texture2D& picture, bool bloom, GLuint target_fbo,
                    int width, int height);
// The image-space outline baseline (LineMethod::image_outline), in place of prepass + lines.
void pass_outline_prepass(const PassContext& ctx);
void pass_image_outline(const PassContext& ctx, bool mask_mode);

}  // namespace bz::render
