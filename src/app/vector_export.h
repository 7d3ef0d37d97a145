#pragma once
// `--svg FILE` of render and reference, and the play key: a frame's exact visible lines as an
// SVG document (render/vector_out/frame_svg.h), written atomically, with a one-line log of
// what it holds (paths before and after chaining, pen-up travel before and after ordering).
#include <filesystem>
#include <string>

#include "render/vector_out/frame_svg.h"

namespace bz::app {

// Writes the SVG and returns the log line (no newline). Throws UserError if it cannot write.
std::string export_frame_svg(const std::filesystem::path& out, const scene::FrameList& frame,
                             const scene::MeshLibrary& meshes, int width, int height,
                             const render::FrameSvgOptions& options = {});

}  // namespace bz::app
