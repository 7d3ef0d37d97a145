#pragma once
// The frame as a list of named passes, built from the style in one place. The renderer runs
// the list in order and times each pass under its name; a new pass is one more entry here.
// Each entry declares the images and buffers it reads and writes (frame_resources.h): the
// renderer allocates what the list names (make_targets), keeps in the view's history what
// it writes of that (FrameHistory), and tells each pass what the passes before it wrote
// (FrameResources). tests/render/frame_passes_test.cpp checks that every read has a writer.
#include <vector>

#include "render/frame_resources.h"
#include "render/passes.h"

namespace bz::render {

struct FramePass {
    FramePass(const char* pass_name, void (*pass_run)(const PassContext&), ResourceSet pass_reads,
              ResourceSet pass_writes, ResourceSet pass_reads_past = {})
        : name(pass_name),
          run(pass_run),
          reads(pass_reads),
          writes(pass_writes),
          reads_past(pass_reads_past) {}

    const char* name;  // the timer's name for it ("prepass", "fill", ...)
    void (*run)(const PassContext& ctx);
    ResourceSet reads;   // written by an earlier pass of the same list
    ResourceSet writes;  // what it draws or stores (wholly, or over what it reads)
    // What it reads from an earlier frame, where the view's history holds it (FrameHistory;
    // a held frame reads the picture it holds and the images its frame wrote).
    ResourceSet reads_past;
};

// What a frame of the style draws: every pass (drawn), or the last picture shown again
// (held: BeamSettings::refresh_hz, only a beam style's, only while the history holds one).
enum class FrameKind { drawn, held };

// Every image the list reads or writes: what its frame needs allocated.
ResourceSet resources_of(const std::vector<FramePass>& list);
// Everything the list writes.
ResourceSet writes_of(const std::vector<FramePass>& list);

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
std::vector<FramePass> frame_passes(const StyleDef& style, const RenderSettings& settings,
                                    FrameKind kind = FrameKind::drawn);

// The passes that draw the 1-pixel accuracy mask into targets.mask (untimed). Styles that draw
// the exact visible feature lines (vector, toon, pop-art, the halo's centre line) share the
// vector mask; sketch masks its own jittered strokes.
std::vector<FramePass> mask_passes(const StyleDef& style, const RenderSettings& settings);

}  // namespace bz::render
