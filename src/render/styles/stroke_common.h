#pragma once
// What the stroke passes share: the uniforms of stroke.vert and the spine test, and the one
// indirect draw of a quad per edge-buffer record.
#include "render/passes.h"

namespace bz::render {

// How a stroke program hides strokes: the spine test against the prepass depth in its fragment
// stage (outline, sketch), or the fixed-function depth test against a mask (halo).
enum class StrokeVisibility { spine_test, depth_test };
// Binds the frame's edge records, instances and depth texture (kTextureUnitDepth) and sets every
// uniform stroke.vert reads, and spine_test.glsl's with StrokeVisibility::spine_test.
void begin_strokes(const PassContext& ctx, const gl::Program& program, StrokeVisibility visibility);
// One quad per record appended by pass_edges, with the count it appended (no read-back).
void draw_edge_strokes(const PassContext& ctx);

}  // namespace bz::render
