#pragma once
// The command line of `beamzone render`: parsed and checked without a model, a level or GL, so
// the fuzz target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <glm/glm.hpp>
#include <string>

#include "cli/camera_options.h"
#include "render/settings.h"
#include "scene/style.h"

namespace bz::app {

const std::string& render_usage();  // the --help text

struct RenderOptions {
    std::string input;
    CameraArgs camera;  // shared with `reference`, so both place the camera alike
    std::string preset = "balanced";
    std::string line_method;  // empty: the preset's
    scene::Style style = scene::Style::vector;
    bool smooth = true;      // filled styles: smooth vertex normals (--shading flat: faces)
    bool smoothing = true;   // halo: cubic silhouette smoothing (--no-smoothing: plain)
    bool one_sided = false;  // toon / pop-art: one-sided outline quads
    glm::dvec3 color{0.25, 1.0, 0.35};
    std::string out = "frame.png";
    std::string mask;
    std::string svg;
    int repeat = 0;
    int copies = 1;
    double copy_step = 1.2;  // --copy-step: copies this many times the model's size apart
    std::string beam{render::kDefaultBeamLook};
    bool lit_share = false;
    bool cluster_culling = true;  // --no-cluster-culling: whole meshes in prepass and fills
    bool hiz_culling = false;     // --hiz-culling: skip edge clusters the prepass hides
    // --prepass-raster: who rasterises the prepass's small triangles (lines/prepass_raster.h)
    render::PrepassRaster prepass_raster = render::PrepassRaster::automatic;
    // --bloom-chain: who computes the mip-chain bloom past its first level (pass_bloom.cpp)
    render::BloomChain bloom_chain = render::BloomChain::automatic;
    // --edge-prefilter: who rules out edges before edges.comp (lines/edge_prefilter.h)
    render::EdgePrefilter edge_prefilter = render::EdgePrefilter::automatic;
    // --clears: who clears the frame's colour images (render/clear_image.h)
    render::ColourClears colour_clears = render::ColourClears::automatic;
    bool material_lines = false;  // --material-lines: edges between materials are lines too
    // --intersection-lines: where surfaces cross, a line
    bool intersection_lines = false;
    bool overwrite = false;  // may replace an existing file that is not a PNG
};

// Throws UsageError naming the bad option.
RenderOptions parse_render_args(Args args);

}  // namespace bz::app
