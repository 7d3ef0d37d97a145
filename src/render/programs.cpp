#include "render/programs.h"

#include <sstream>

#include "core/paths.h"
#include "gl/driver.h"
#include "render/beam/bloom_kernel.h"
#include "render/lines/edge_culling.h"
#include "render/shader_interface.h"
#include "render/targets.h"

namespace bz::render {

namespace {

std::string glsl_array(const std::vector<float>& v) {
    std::ostringstream out;
    out.precision(9);
    out << "float[](";
    for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << std::showpoint << v[i];
    out << ")";
    return out.str();
}

// Every program of the pipeline gets the shader interface's #defines (render/shader_interface.h)
// ahead of its own.
gl::Program program(const std::vector<gl::StageFile>& stages,
                    const std::vector<std::string>& defines = {}) {
    std::vector<std::string> all = shader_interface_defines();
    all.insert(all.end(), defines.begin(), defines.end());
    return gl::Program(stages, all);
}

}  // namespace

gl::Program load_bloom_blur(const RenderSettings& settings, bool glow_persistence) {
    const BloomKernel k = bloom_kernel(settings.bloom_taps, settings.bloom_sigma_px);
    const auto dir = shaders_dir();
    std::vector<std::string> defines = {"BLOOM_FETCHES " + std::to_string(k.weights.size()),
                                        "BLOOM_OFFSETS " + glsl_array(k.offsets),
                                        "BLOOM_WEIGHTS " + glsl_array(k.weights)};
    if (glow_persistence) defines.push_back("GLOW_PHOSPHOR 1");
    // Its last direction marks the lit tiles (shaders/beam/lit_tiles.glsl).
    defines.push_back("LIT_TILES 1");
    defines.push_back("LIT_TILE_SIZE " + std::to_string(kLitTileSize));
    return program({{GL_VERTEX_SHADER, dir / "fullscreen.vert"},
                    {GL_FRAGMENT_SHADER, dir / "beam/bloom_blur.frag"}},
                   std::move(defines));
}

Programs load_programs(const RenderSettings& settings) {
    const auto dir = shaders_dir();
    auto stage = [&](GLenum type, const char* file) { return gl::StageFile{type, dir / file}; };
    Programs p;
    p.prepass = program({stage(GL_VERTEX_SHADER, "lines/prepass.vert")});
    p.prepass_raster = program({stage(GL_COMPUTE_SHADER, "lines/prepass_raster.comp")});
    p.depth_resolve = program({stage(GL_VERTEX_SHADER, "lines/depth_resolve.vert"),
                               stage(GL_FRAGMENT_SHADER, "lines/depth_resolve.frag")});
    p.occlusion_layer = program({stage(GL_VERTEX_SHADER, "lines/prepass.vert"),
                                 stage(GL_FRAGMENT_SHADER, "lines/occlusion_layer.frag")});
    // The beam's line stages mark the screen tiles they light (shaders/beam/beam_tiles.glsl).
    const std::vector<std::string> beam_tiles = {"BEAM_TILES 1",
                                                 "TILE_SIZE " + std::to_string(kScreenTileSize)};
    p.lines = program(
        {stage(GL_VERTEX_SHADER, "lines/lines.vert"), stage(GL_GEOMETRY_SHADER, "lines/lines.geom"),
         stage(GL_FRAGMENT_SHADER, "lines/lines.frag")},
        beam_tiles);
    p.mask = program(
        {stage(GL_VERTEX_SHADER, "lines/lines.vert"), stage(GL_GEOMETRY_SHADER, "lines/lines.geom"),
         stage(GL_FRAGMENT_SHADER, "lines/lines.frag")},
        {"MASK_MODE 1"});
    std::vector<std::string> beam_levels = beam_tiles;
    beam_levels.push_back("OCCLUSION_LEVELS 1");
    p.lines_dim = program(
        {stage(GL_VERTEX_SHADER, "lines/lines.vert"), stage(GL_GEOMETRY_SHADER, "lines/lines.geom"),
         stage(GL_FRAGMENT_SHADER, "lines/lines.frag")},
        beam_levels);
    const std::string edge_group =
        "EDGE_GROUP_SIZE " + std::to_string(edge_group_size(gl::is_software_renderer()));
    p.edges = program({stage(GL_COMPUTE_SHADER, "lines/edges.comp")}, {edge_group});
    p.edges_listed =
        program({stage(GL_COMPUTE_SHADER, "lines/edges.comp")}, {edge_group, "EDGE_WORK_LISTED 1"});
    p.edges_normals = program({stage(GL_COMPUTE_SHADER, "lines/edges.comp")},
                              {edge_group, "EDGE_RECORD_NORMALS 1"});
    p.edges_listed_normals = program({stage(GL_COMPUTE_SHADER, "lines/edges.comp")},
                                     {edge_group, "EDGE_WORK_LISTED 1", "EDGE_RECORD_NORMALS 1"});
    p.spine_visibility = program({stage(GL_COMPUTE_SHADER, "lines/spine_visibility.comp")});
    p.intersections = program({stage(GL_COMPUTE_SHADER, "lines/intersections.comp")});
    p.depth_tiles = program({stage(GL_COMPUTE_SHADER, "lines/depth_tiles.comp")});
    auto quads = [&](std::vector<std::string> defines) {
        const std::vector<gl::StageFile> stages = {
            stage(GL_VERTEX_SHADER, "lines/edge_quad.vert"),
            stage(GL_FRAGMENT_SHADER, "lines/edge_quad.frag")};
        std::vector<std::string> sampled = defines;
        sampled.push_back("SPINE_SAMPLES_ONLY 1");
        return QuadPrograms{.sampled = program(stages, sampled),
                            .tested = program(stages, defines)};
    };
    p.edge_quads = quads(beam_tiles);
    p.edge_quads_mask = quads({"MASK_MODE 1"});
    p.edge_quads_dim = quads(beam_levels);
    p.hud =
        program({stage(GL_VERTEX_SHADER, "hud/hud.vert"), stage(GL_GEOMETRY_SHADER, "hud/hud.geom"),
                 stage(GL_FRAGMENT_SHADER, "hud/hud.frag")},
                beam_tiles);
    // The passes that know where light is mark the composite's lit tiles (lit_tiles.glsl).
    const std::string lit_tile_size = "LIT_TILE_SIZE " + std::to_string(kLitTileSize);
    // The HUD of the dark looks is drawn after the bloom (pass_hud.cpp): its lit fragments
    // mark the composite's lit tiles.
    p.hud_lit_tiles =
        program({stage(GL_VERTEX_SHADER, "hud/hud.vert"), stage(GL_GEOMETRY_SHADER, "hud/hud.geom"),
                 stage(GL_FRAGMENT_SHADER, "hud/hud.frag")},
                {"LIT_TILES 1", lit_tile_size});
    p.bloom_down = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                            stage(GL_FRAGMENT_SHADER, "beam/bloom_down.frag")},
                           {"LIT_TILES 1", lit_tile_size});
    p.bloom_blur = load_bloom_blur(settings, false);
    p.bloom_blur_glow = load_bloom_blur(settings, true);
    p.composite = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                           stage(GL_FRAGMENT_SHADER, "beam/composite.frag")});
    const std::string tile_size = "TILE_SIZE " + std::to_string(kScreenTileSize);
    const auto composite = [&](const char* vertex, std::vector<std::string> defines) {
        return program(
            {stage(GL_VERTEX_SHADER, vertex), stage(GL_FRAGMENT_SHADER, "beam/composite.frag")},
            std::move(defines));
    };
    p.composite_tiles = composite("beam/lit_tiles.vert", {lit_tile_size});
    p.bloom_down_tiles = program({stage(GL_VERTEX_SHADER, "beam/composite_tiles.vert"),
                                  stage(GL_FRAGMENT_SHADER, "beam/bloom_down.frag")},
                                 {tile_size, "LIT_TILES 1", lit_tile_size});
    for (std::size_t power_law = 0; power_law < 2; ++power_law) {
        const std::string decay = "POWER_LAW " + std::to_string(power_law);
        p.composite_phosphor[power_law] =
            composite("fullscreen.vert", {lit_tile_size, "PHOSPHOR 1", decay});
        p.composite_tiles_phosphor[power_law] =
            composite("beam/lit_tiles.vert", {lit_tile_size, "PHOSPHOR 1", decay});
    }
    p.tile_list = program({stage(GL_COMPUTE_SHADER, "beam/tile_list.comp")}, {lit_tile_size});
    p.clear_image = program({stage(GL_COMPUTE_SHADER, "clear_image.comp")});
    p.bloom_chain = program({stage(GL_COMPUTE_SHADER, "beam/bloom_chain.comp")});
    p.bloom_up = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                          stage(GL_FRAGMENT_SHADER, "beam/bloom_up.frag")},
                         {"LIT_TILES 1", lit_tile_size});
    p.bloom_up_glow = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                               stage(GL_FRAGMENT_SHADER, "beam/bloom_up.frag")},
                              {"GLOW_PHOSPHOR 1", "LIT_TILES 1", lit_tile_size});
    p.outline_prepass = program({stage(GL_VERTEX_SHADER, "styles/outline_prepass.vert"),
                                 stage(GL_FRAGMENT_SHADER, "styles/outline_prepass.frag")});
    p.image_outline = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                               stage(GL_FRAGMENT_SHADER, "styles/image_outline.frag")});
    p.image_outline_mask = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                    stage(GL_FRAGMENT_SHADER, "styles/image_outline.frag")},
                                   {"MASK_MODE 1"});
    const auto fill = [&](const char* define) {
        return program({stage(GL_VERTEX_SHADER, "styles/fill.vert"),
                        stage(GL_FRAGMENT_SHADER, "styles/fill.frag")},
                       {define});
    };
    p.fill_toon = fill("FILL_TOON 1");
    p.fill_pop_art = fill("FILL_POP_ART 1");
    p.fill_paper = fill("FILL_PAPER 1");
    p.shrunk_depth = program({stage(GL_VERTEX_SHADER, "styles/fill.vert")}, {"SHRINK 1"});
    p.ink_composite = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                               stage(GL_FRAGMENT_SHADER, "styles/ink_composite.frag")});
    // Over the screen tiles the HUD lit, grown by its halo (pass_ink_composite.cpp).
    p.ink_composite_tiles = program({stage(GL_VERTEX_SHADER, "styles/marked_tiles.vert"),
                                     stage(GL_FRAGMENT_SHADER, "styles/ink_composite.frag")},
                                    {tile_size});
    const auto stroke = [&](const char* frag, std::vector<std::string> defines) {
        return program(
            {stage(GL_VERTEX_SHADER, "styles/stroke.vert"), stage(GL_FRAGMENT_SHADER, frag)},
            std::move(defines));
    };
    p.outline = stroke("styles/outline.frag", {"STROKE_OUTLINE 1"});
    p.outline_levels_mask = stroke("styles/outline.frag", {"STROKE_OUTLINE 1", "MASK_MODE 1"});
    p.sketch = stroke("styles/sketch.frag", {"STROKE_SKETCH 1"});
    p.sketch_mask = stroke("styles/sketch.frag", {"STROKE_SKETCH 1", "MASK_MODE 1"});
    // The soft halo's quads mark the tiles they cover; the halo is laid over those alone.
    p.halo_glow = stroke("styles/halo.frag", {"STROKE_HALO 1", "HALO_GLOW 1", "BEAM_TILES 1",
                                              "TILE_SIZE " + std::to_string(kScreenTileSize)});
    p.halo = stroke("styles/halo.frag", {"STROKE_HALO 1"});
    p.halo_apply = program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                            stage(GL_FRAGMENT_SHADER, "styles/halo_apply.frag")});
    p.halo_apply_tiles = program({stage(GL_VERTEX_SHADER, "styles/marked_tiles.vert"),
                                  stage(GL_FRAGMENT_SHADER, "styles/halo_apply.frag")},
                                 {tile_size});
    return p;
}

}  // namespace bz::render
