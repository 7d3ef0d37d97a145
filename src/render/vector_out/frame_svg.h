#pragma once
// A frame's lines as an SVG document: the exact visible segments of the CPU reference
// (geometry/reference), chained into polylines and ordered for a pen plotter, one group per
// line kind, stroked in the frame style's colours. No GL: it works headless and in play alike.
#include <cstddef>
#include <string>

#include "render/reference_frame.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::render {

struct FrameSvgOptions {
    ReferenceFrameOptions reference;
    double chain_tolerance_px = 0.01;  // segment ends closer than this are joined
    bool hud = true;                   // the frame's HUD lines, as a group of their own
};

struct FrameSvgStats {
    geo::ReferenceStats reference;
    std::size_t segments = 0;       // visible segments: the paths before chaining
    std::size_t paths = 0;          // polylines after chaining
    double travel_before_px = 0.0;  // pen-up travel in the order chaining left them
    double travel_after_px = 0.0;   // ... and after greedy nearest-end ordering
    double reference_ms = 0.0;      // finding the visible segments
    double chain_order_ms = 0.0;    // chaining and ordering
    double write_ms = 0.0;          // formatting the document
};

// The document, in the frame's pixel units (width x height, y down as SVG has it).
std::string frame_svg(const scene::FrameList& frame, const scene::MeshLibrary& meshes, int width,
                      int height, const FrameSvgOptions& options = {},
                      FrameSvgStats* stats = nullptr);

}  // namespace bz::render
