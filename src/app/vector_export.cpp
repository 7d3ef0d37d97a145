#include "app/vector_export.h"

#include <chrono>
#include <cstdio>

#include "core/io/file_io.h"
#include "core/text/printable.h"

namespace bz::app {

std::string export_frame_svg(const std::filesystem::path& out, const scene::FrameList& frame,
                             const scene::MeshLibrary& meshes, int width, int height,
                             const render::FrameSvgOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    render::FrameSvgStats s;
    const std::string doc = render::frame_svg(frame, meshes, width, height, options, &s);
    write_file_atomic(out, doc);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: %zu segments -> %zu paths after chaining; pen-up travel %.0f px -> %.0f px "
                  "after ordering; %zu feature edges, %zu rays; %.0f ms (lines %.0f, chain and "
                  "order %.0f, format %.0f)",
                  printable(out.string()).c_str(), s.segments, s.paths, s.travel_before_px,
                  s.travel_after_px, s.reference.feature_edges, s.reference.rays, ms,
                  s.reference_ms, s.chain_order_ms, s.write_ms);
    return line;
}

}  // namespace bz::app
