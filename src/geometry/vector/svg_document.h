#pragma once
// Writes polylines as an SVG 1.1 document: one <g> per group (an Inkscape layer too, so an
// editor lists it and a plotter tool can drop it), one <path> per polyline.
#include <span>
#include <string>
#include <vector>

#include "geometry/vector/polylines.h"

namespace bz::geo {

struct SvgGroup {
    std::string id;             // an XML name: letters, digits, '-' and '_'
    std::string stroke;         // "#rrggbb", the group's colour
    double width = 1.0;         // stroke width in pixels
    std::string dash;           // stroke-dasharray, "" for solid
    bool dash_offsets = false;  // each path's stroke-dashoffset is its Polyline::dash_offset
    std::vector<Polyline> paths;
    std::vector<std::string> path_stroke;  // per path, "" (or missing) inherits the group's
};

// Points are window coordinates (y up, as the reference gives them); the document flips them
// to SVG's y down over a `height`-pixel canvas. `background` "#rrggbb", or "" for none.
// Coordinates are written with 3 decimals (1/1000 px).
std::string svg_document(int width, int height, const std::string& background,
                         std::span<const SvgGroup> groups);

// "#rrggbb" of a colour, each channel clamped to [0, 1] (an HDR colour keeps its hue only
// when no channel exceeds 1; the brightest channel is scaled to 1 first).
std::string svg_colour(double r, double g, double b);

}  // namespace bz::geo
