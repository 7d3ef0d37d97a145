#pragma once
// The style table: every look a frame can be drawn in (scene::Style, style.h), with its name,
// old names, help text, definition (what the renderer draws, scene/style_def.h), HUD theme and
// palette, in this one file.
// The level loader, the settings file, the command line, help texts, the options menu and the
// play key (F6) all read it; the renderer draws from the StyleDef.
//
// A style that only sets parameters (a new paper tone, other stroke widths) is added with its
// value in `Style` (style.h) and, here, kLastStyle and its `case` in style_entry(). The switch
// has no default, so the compiler (-Wswitch, an error with BEAMZONE_WERROR) names a style left
// out.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/style.h"
#include "scene/style_def.h"

namespace bz::scene {

// The last style of scene::Style (style.h): all_styles() lists 0..kLastStyle.
inline constexpr Style kLastStyle = Style::technical;

struct StyleEntry {
    std::string_view name;                    // canonical, as levels and settings write it
    std::array<std::string_view, 1> aliases;  // old names that still load ("" for none)
    std::string_view help;                    // one line for --help and the docs
    StyleDef def;
};

namespace style_detail {

// The filled styles: a fill pass and a line pass over a light background, without bloom,
// with the HUD in ink.
inline StyleDef filled(Style id, FillPass fill, LinePass lines, glm::vec3 background) {
    StyleDef s;
    s.id = id;
    s.fill = fill;
    s.lines = lines;
    s.bloom = false;
    s.background = background;
    s.hud.ink = true;
    s.palette.remap = true;
    return s;
}

inline StyleDef beam(Style id, bool hidden_lines_removed) {
    StyleDef s;
    s.id = id;
    s.hidden_lines_removed = hidden_lines_removed;
    return s;
}

}  // namespace style_detail

// The table. Every style has exactly one case.
inline StyleEntry style_entry(Style style) {
    using style_detail::filled;
    switch (style) {
        case Style::vector:
            return {"vector",
                    {"occluded"},
                    "glowing vector lines, hidden lines removed",
                    style_detail::beam(style, true)};
        case Style::vector_xray:
            return {"vector-xray",
                    {"arcade"},
                    "vector lines without hidden-line removal",
                    style_detail::beam(style, false)};
        case Style::toon: {
            StyleDef s = filled(style, FillPass::toon, LinePass::outline,
                                {0.78f, 0.86f, 0.93f});  // a pale sky
            s.toon_bands = 3;
            s.outline.width_px = 3.0f;
            s.outline.overdraw = 0.02f;  // Castro & Macedo: closes gaps between quads on curves
            s.outline.quad = OutlineQuad::centred;
            return {"toon", {""}, "cel-shaded fill with ink outlines", s};
        }
        case Style::sketch: {
            StyleDef s = filled(style, FillPass::paper, LinePass::sketch,
                                {0.94f, 0.92f, 0.86f});  // off-white drawing paper
            s.outline.ink = {0.16f, 0.15f, 0.14f};       // graphite
            return {"sketch", {""}, "pencil strokes on paper", s};
        }
        case Style::pop_art: {
            StyleDef s = filled(style, FillPass::pop_art, LinePass::outline,
                                {0.99f, 0.95f, 0.80f});  // newsprint
            s.outline.width_px = 1.6f;                   // a single fine line, no jitter
            s.outline.overdraw = 0.0f;
            return {"pop-art", {""}, "flat colour, Ben-Day dots and a fine outline", s};
        }
        case Style::halo: {
            StyleDef s = filled(style, FillPass::paper, LinePass::halo, {0.97f, 0.97f, 0.95f});
            s.paper_tint = 0.3f;  // a wash of the object's colour, so halos show on what is behind
            s.outline.ink = {0.05f, 0.05f, 0.08f};
            return {"halo", {""}, "haloed silhouette strokes over paper", s};
        }
        case Style::technical: {
            StyleDef s = filled(style, FillPass::paper, LinePass::outline, {1.0f, 1.0f, 1.0f});
            s.outline.width_px = 1.5f;
            s.outline.overdraw = 0.0f;
            s.outline.ink = {0.0f, 0.0f, 0.0f};
            s.hidden.levels = 3;  // SVG: hidden lines dashed and thinner, grouped by level
            return {"technical", {""}, "black ink on white; SVG adds dashed hidden lines", s};
        }
    }
    return {"", {""}, "", StyleDef{}};  // not reached: every style has its case
}

// The accepted names (style.h) as strings: the settings file's loader takes them (platform
// may not link scene).
const std::vector<std::string>& accepted_style_name_strings();
// "  vector        glowing vector lines, ...", one line per style, for --help.
std::string style_help();

}  // namespace bz::scene
