#include "geometry/vector/svg_document.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace bz::geo {

namespace {

void append_number(std::string& out, double v) {
    char buf[32];
    if (std::abs(v) < 0.0005) v = 0.0;  // no "-0.000"
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 3);
    std::string_view s(buf, static_cast<std::size_t>(r.ptr - buf));
    // Trailing zeros carry nothing: "12.500" -> "12.5", "3.000" -> "3".
    if (s.find('.') != std::string_view::npos) {
        while (s.back() == '0') s.remove_suffix(1);
        if (s.back() == '.') s.remove_suffix(1);
    }
    out.append(s);
}

void append_path(std::string& out, const Polyline& p, int height, const std::string& stroke,
                 bool dash_offset) {
    out += "<path d=\"M";
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        if (i == 1) out += " L";
        out += ' ';
        append_number(out, p.points[i].x);
        out += ' ';
        append_number(out, height - p.points[i].y);
    }
    out += '"';
    if (!stroke.empty()) out += " stroke=\"" + stroke + "\"";
    if (dash_offset) {
        out += " stroke-dashoffset=\"";
        append_number(out, p.dash_offset);
        out += '"';
    }
    out += "/>\n";
}

}  // namespace

std::string svg_colour(double r, double g, double b) {
    const double m = std::max({r, g, b});
    if (m > 1.0) r /= m, g /= m, b /= m;
    auto byte = [](double v) {
        return static_cast<int>(
            std::lround(std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0) * 255.0));
    };
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(r), byte(g), byte(b));
    return buf;
}

std::string svg_document(int width, int height, const std::string& background,
                         std::span<const SvgGroup> groups) {
    std::string out;
    std::size_t points = 0;
    for (const SvgGroup& g : groups)
        for (const Polyline& p : g.paths) points += p.points.size();
    out.reserve(512 + points * 16);
    const std::string w = std::to_string(width), h = std::to_string(height);
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out +=
        "<svg xmlns=\"http://www.w3.org/2000/svg\" "
        "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" version=\"1.1\" "
        "width=\"" +
        w + "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
    if (!background.empty()) {
        out += "<rect id=\"background\" x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h +
               "\" fill=\"" + background + "\"/>\n";
    }
    for (const SvgGroup& g : groups) {
        out += "<g id=\"" + g.id + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + g.id +
               "\" fill=\"none\" stroke=\"" + g.stroke + "\" stroke-width=\"";
        append_number(out, g.width);
        out += "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
        if (!g.dash.empty()) out += " stroke-dasharray=\"" + g.dash + "\"";
        out += ">\n";
        for (std::size_t i = 0; i < g.paths.size(); ++i) {
            if (g.paths[i].points.empty()) continue;
            append_path(out, g.paths[i], height,
                        i < g.path_stroke.size() ? g.path_stroke[i] : std::string(),
                        g.dash_offsets);
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

}  // namespace bz::geo
