#pragma once
// What the stroke passes share: the uniforms of stroke.vert and the spine test, and the one
// indirect draw of a quad per edge-buffer record.
#include "render/passes.h"

namespace bz::render {

// Binds the frame's edge records, instances and depth texture (unit 0) and sets every
// uniform stroke.vert and spine_test.glsl read.
void begin_strokes(const PassContext& ctx, const gl::Program& program);
// One quad per record appended by pass_edges, with the count it appended (no read-back).
void draw_edge_strokes(const PassContext& ctx);

}  // namespace bz::render
