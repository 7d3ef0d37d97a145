#pragma once
// The passes of one frame, one file each: prepass -> lines -> hud -> bloom -> composite.
// Each states the whole GL state it needs (gl::apply), so order is the only coupling.
#include <span>

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
};

void pass_prepass(const PassContext& ctx);
// mask_mode: draw the 1-pixel visible-spine mask into targets.mask instead of shaded lines.
void pass_lines(const PassContext& ctx, bool mask_mode);
void pass_hud(const PassContext& ctx, const gl::VertexArray& hud_vao, GLsizei vertex_count);
void pass_bloom(const PassContext& ctx);
void pass_composite(const PassContext& ctx, GLuint target_fbo, int width, int height);
// The image-space outline baseline (LineMethod::image_outline), in place of prepass + lines.
void pass_outline_prepass(const PassContext& ctx);
void pass_image_outline(const PassContext& ctx, bool mask_mode);

}  // namespace bz::render
