#include "render/styles/style_def.h"

#include <array>

namespace bz::render {

namespace {

StyleDef vector_style() {
    return StyleDef{};
}

StyleDef vector_xray() {
    StyleDef s;
    s.id = scene::Style::vector_xray;
    s.hidden_lines_removed = false;
    return s;
}

// The filled styles: a fill pass and a line pass over a light background, without bloom.
StyleDef filled(scene::Style id, FillPass fill, LinePass lines, glm::vec3 background) {
    StyleDef s;
    s.id = id;
    s.fill = fill;
    s.lines = lines;
    s.bloom = false;
    s.background = background;
    return s;
}

StyleDef toon() {
    StyleDef s = filled(scene::Style::toon, FillPass::toon, LinePass::outline,
                        {0.78f, 0.86f, 0.93f});  // a pale sky
    s.toon_bands = 3;
    s.outline.width_px = 3.0f;
    s.outline.overdraw = 0.02f;  // closes the gaps between quads on curves (Castro & Macedo)
    s.outline.quad = OutlineQuad::centred;
    return s;
}

StyleDef sketch() {
    StyleDef s = filled(scene::Style::sketch, FillPass::paper, LinePass::sketch,
                        {0.94f, 0.92f, 0.86f});  // off-white drawing paper
    s.outline.ink = {0.16f, 0.15f, 0.14f};       // graphite
    return s;
}

StyleDef pop_art() {
    StyleDef s = filled(scene::Style::pop_art, FillPass::pop_art, LinePass::outline,
                        {0.99f, 0.95f, 0.80f});  // newsprint
    s.outline.width_px = 1.6f;                   // a single fine line, no jitter
    s.outline.overdraw = 0.0f;
    return s;
}

StyleDef halo() {
    StyleDef s = filled(scene::Style::halo, FillPass::paper, LinePass::halo, {0.97f, 0.97f, 0.95f});
    s.paper_tint = 0.3f;  // a wash of the object's colour, so halos show against what is behind
    s.outline.ink = {0.05f, 0.05f, 0.08f};
    return s;
}

}  // namespace

const StyleDef& style_def(scene::Style style) {
    static const std::array<StyleDef, 6> defs = {vector_style(), vector_xray(), toon(),
                                                 sketch(),       pop_art(),     halo()};
    const auto i = static_cast<std::size_t>(style);
    return i < defs.size() ? defs[i] : defs[0];
}

}  // namespace bz::render
