#pragma once
// Fixed-function state for one draw, applied in one place. Every pass states the whole of it,
// so no pass depends on what the previous one left behind.
#include "gl/gl.h"

namespace bz::gl {

// alpha: src * a + dst * (1 - a); min: the darker of the two, per channel (order-independent ink)
enum class Blend { none, max, add, alpha, min };
enum class DepthTest { off, less, greater, always };

struct PipelineState {
    DepthTest depth_test = DepthTest::off;
    bool depth_write = false;
    bool color_write = true;
    Blend blend = Blend::none;
    bool cull_back = false;
    bool depth_clamp = false;
    bool depth_zero_to_one = true;  // glClipControl depth range: [0,1] for reversed-Z
    // > 0: draw only into the bottom `scissor_rows` pixel rows (the 3D view below a HUD band).
    // Clears obey the scissor too, so a pass clears before it applies a scissored state.
    int scissor_rows = 0;
    int scissor_width = 0;
};

void apply(const PipelineState& state);

}  // namespace bz::gl
