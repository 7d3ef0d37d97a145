#include "render/programs.h"

#include <sstream>

#include "core/paths.h"
#include "render/bloom_kernel.h"

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

}  // namespace

gl::Program load_bloom_blur(const RenderSettings& settings) {
    const BloomKernel k = bloom_kernel(settings.bloom_taps, settings.bloom_sigma_px);
    const auto dir = shaders_dir();
    return gl::Program({{GL_VERTEX_SHADER, dir / "fullscreen.vert"}, {GL_FRAGMENT_SHADER, dir / "bloom_blur.frag"}},
                       {"BLOOM_FETCHES " + std::to_string(k.weights.size()),
                        "BLOOM_OFFSETS " + glsl_array(k.offsets), "BLOOM_WEIGHTS " + glsl_array(k.weights)});
}

Programs load_programs(const RenderSettings& settings) {
    const auto dir = shaders_dir();
    auto stage = [&](GLenum type, const char* file) { return gl::StageFile{type, dir / file}; };
    Programs p;
    p.prepass = gl::Program({stage(GL_VERTEX_SHADER, "prepass.vert")});
    p.lines = gl::Program({stage(GL_VERTEX_SHADER, "lines.vert"), stage(GL_GEOMETRY_SHADER, "lines.geom"),
                           stage(GL_FRAGMENT_SHADER, "lines.frag")});
    p.mask = gl::Program({stage(GL_VERTEX_SHADER, "lines.vert"), stage(GL_GEOMETRY_SHADER, "lines.geom"),
                          stage(GL_FRAGMENT_SHADER, "lines.frag")},
                         {"MASK_MODE 1"});
    p.edges = gl::Program({stage(GL_COMPUTE_SHADER, "edges.comp")});
    p.spine_visibility = gl::Program({stage(GL_COMPUTE_SHADER, "spine_visibility.comp")});
    p.edge_quads = gl::Program({stage(GL_VERTEX_SHADER, "edge_quad.vert"), stage(GL_FRAGMENT_SHADER, "edge_quad.frag")});
    p.edge_quads_mask = gl::Program(
        {stage(GL_VERTEX_SHADER, "edge_quad.vert"), stage(GL_FRAGMENT_SHADER, "edge_quad.frag")}, {"MASK_MODE 1"});
    p.hud = gl::Program({stage(GL_VERTEX_SHADER, "hud.vert"), stage(GL_GEOMETRY_SHADER, "hud.geom"),
                         stage(GL_FRAGMENT_SHADER, "hud.frag")});
    p.bloom_down = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                stage(GL_FRAGMENT_SHADER, "bloom_down.frag")});
    p.bloom_blur = load_bloom_blur(settings);
    p.composite = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                               stage(GL_FRAGMENT_SHADER, "composite.frag")});
    p.bloom_up = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"), stage(GL_FRAGMENT_SHADER, "bloom_up.frag")});
    p.phosphor = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"), stage(GL_FRAGMENT_SHADER, "phosphor.frag")});
    p.outline_prepass = gl::Program({stage(GL_VERTEX_SHADER, "outline_prepass.vert"),
                                     stage(GL_FRAGMENT_SHADER, "outline_prepass.frag")});
    p.image_outline = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                   stage(GL_FRAGMENT_SHADER, "image_outline.frag")});
    p.image_outline_mask = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                        stage(GL_FRAGMENT_SHADER, "image_outline.frag")},
                                       {"MASK_MODE 1"});
    const auto fill = [&](const char* define) {
        return gl::Program({stage(GL_VERTEX_SHADER, "fill.vert"), stage(GL_FRAGMENT_SHADER, "fill.frag")},
                           {define});
    };
    p.fill_toon = fill("FILL_TOON 1");
    p.fill_pop_art = fill("FILL_POP_ART 1");
    p.fill_paper = fill("FILL_PAPER 1");
    p.shrunk_depth = gl::Program({stage(GL_VERTEX_SHADER, "fill.vert")}, {"SHRINK 1"});
    p.ink_composite = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                   stage(GL_FRAGMENT_SHADER, "ink_composite.frag")});
    const auto stroke = [&](const char* frag, std::vector<std::string> defines) {
        return gl::Program({stage(GL_VERTEX_SHADER, "stroke.vert"), stage(GL_FRAGMENT_SHADER, frag)},
                           std::move(defines));
    };
    p.outline = stroke("outline.frag", {"STROKE_OUTLINE 1"});
    p.sketch = stroke("sketch.frag", {"STROKE_SKETCH 1"});
    p.sketch_mask = stroke("sketch.frag", {"STROKE_SKETCH 1", "MASK_MODE 1"});
    p.halo_glow = stroke("halo.frag", {"STROKE_HALO 1", "HALO_GLOW 1"});
    p.halo = stroke("halo.frag", {"STROKE_HALO 1"});
    p.halo_apply = gl::Program({stage(GL_VERTEX_SHADER, "fullscreen.vert"),
                                stage(GL_FRAGMENT_SHADER, "halo_apply.frag")});
    return p;
}

}  // namespace bz::render
