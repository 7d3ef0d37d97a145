#pragma once
// The frame as a list of named passes, built from the style in one place. The renderer runs
// the list in order and times each pass under its name; a new pass is one more entry here.
#include <vector>

#include "render/passes.h"

namespace bz::render {

struct FramePass {
    const char* name;  // the timer's name for it ("prepass", "fill", ...)
    void (*run)(const PassContext& ctx);
};

// Whether the frame's passes read the edge buffer (the mesh cache then builds edge lists): the
// stroke styles do, and the beam styles with LineMethod::compute.
bool style_needs_edge_buffer(const StyleDef& style, const RenderSettings& settings);
// The same for the mask passes: with LineMethod::compute every exact-line style's mask is
// drawn from the edge buffer, so that it is the vector style's mask to the pixel.
bool mask_needs_edge_buffer(const StyleDef& style, const RenderSettings& settings);

// With LineMethod::automatic these two say whether a frame may need the edge buffer.
//
// frame_passes and mask_passes take the frame's resolved method (resolve_line_method), never
// LineMethod::automatic.
std::vector<FramePass> frame_passes(const StyleDef& style, const RenderSettings& settings);

// The passes that draw the 1-pixel accuracy mask into targets.mask (untimed). Styles that draw
// the exact visible feature lines (vector, toon, pop-art, the halo's centre line) share the
// vector mask; sketch masks its own jittered strokes.
std::vector<FramePass> mask_passes(const StyleDef& style, const RenderSettings& settings);

}  // namespace bz::render
