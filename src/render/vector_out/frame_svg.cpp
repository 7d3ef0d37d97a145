#include "render/vector_out/frame_svg.h"

#include <algorithm>
#include <array>
#include <chrono>

#include "geometry/vector/path_order.h"
#include "geometry/vector/svg_document.h"
#include "scene/style_table.h"

namespace bz::render {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The group order in the document, and each kind's name there.
constexpr std::array<std::pair<geo::LineKind, const char*>, 5> kKinds{{
    {geo::LineKind::silhouette, "silhouette"},
    {geo::LineKind::crease, "crease"},
    {geo::LineKind::boundary, "boundary"},
    {geo::LineKind::material, "material"},
    {geo::LineKind::intersection, "intersection"},
}};

// The style's stroke: beam styles draw each object in its own colour on black; the paper
// styles in their ink, as wide as their strokes.
struct Stroke {
    bool per_object_colour = true;
    std::string ink;
    double width = 1.5;
    std::string background = "#000000";
    glm::vec3 ink_rgb{0.0f};
    glm::vec3 paper_rgb{0.0f};
};

Stroke stroke_of(const scene::StyleDef& s) {
    Stroke out;
    auto colour = [](glm::vec3 c) { return geo::svg_colour(c.r, c.g, c.b); };
    switch (s.lines) {
        case scene::LinePass::beam:
            return out;
        case scene::LinePass::outline:
            out.width = s.outline.width_px;
            break;
        case scene::LinePass::sketch:
            out.width = s.sketch.width_px;
            break;
        case scene::LinePass::halo:
            out.width = s.halo.inner_px + s.halo.outer_px;
            break;
    }
    out.per_object_colour = false;
    out.ink = colour(s.outline.ink);
    out.background = colour(s.background);
    out.ink_rgb = s.outline.ink;
    out.paper_rgb = s.background;
    return out;
}

// Keeps the parts of segments below window height `top` (the play HUD's band is above it).
void clip_below(std::vector<geo::VisibleSegment>& segments, double top) {
    std::vector<geo::VisibleSegment> kept;
    kept.reserve(segments.size());
    for (geo::VisibleSegment s : segments) {
        if (s.a.y > top && s.b.y > top) continue;
        if (s.a.y > top || s.b.y > top) {
            glm::dvec2& out = s.a.y > top ? s.a : s.b;
            const glm::dvec2 in = s.a.y > top ? s.b : s.a;
            out = in + (out - in) * ((top - in.y) / (out.y - in.y));
        }
        kept.push_back(s);
    }
    segments = std::move(kept);
}

geo::SvgGroup hud_group(const scene::FrameList& frame, int width, int height, double line_width) {
    geo::SvgGroup g;
    g.id = "hud";
    g.stroke = "#33ff4d";
    g.width = line_width;
    const glm::dvec2 centre(width * 0.5, height * 0.5);
    for (const scene::HudLine& l : frame.hud) {
        geo::Polyline p;
        p.points = {centre + glm::dvec2(l.a) * (height * 0.5),
                    centre + glm::dvec2(l.b) * (height * 0.5)};
        g.paths.push_back(std::move(p));
        g.path_stroke.push_back(geo::svg_colour(l.color.r, l.color.g, l.color.b));
    }
    return g;
}

}  // namespace

std::string frame_svg(const scene::FrameList& frame, const scene::MeshLibrary& meshes, int width,
                      int height, const FrameSvgOptions& options, FrameSvgStats* stats_out) {
    FrameSvgStats stats;
    auto t0 = Clock::now();
    const scene::StyleDef& def = scene::style_entry(frame.style).def;
    ReferenceFrameOptions ref = options.reference;
    if (def.hidden_lines_removed)
        ref.sampling.hidden_levels = std::clamp(def.hidden.levels, 0, geo::kMaxOcclusionLevel);
    std::vector<geo::VisibleSegment> segments =
        reference_frame_segments(frame, meshes, width, height, ref, &stats.reference);
    if (frame.view_top < 1.0f) clip_below(segments, (frame.view_top * 0.5 + 0.5) * height);
    stats.reference_ms = ms_since(t0);
    stats.segments = segments.size();

    t0 = Clock::now();
    const Stroke stroke = stroke_of(def);
    // Visible lines chain into polylines; hidden ones stay single segments in their own
    // direction, so each dash pattern starts at its edge's first end.
    const auto hidden_begin =
        std::stable_partition(segments.begin(), segments.end(),
                              [](const geo::VisibleSegment& s) { return s.level == 0; });
    std::vector<geo::Polyline> chained =
        geo::chain_segments(std::span(segments.begin(), hidden_begin), options.chain_tolerance_px);
    const std::vector<geo::Polyline> hidden =
        geo::single_segments(std::span(hidden_begin, segments.end()));
    stats.paths = chained.size() + hidden.size();
    std::vector<geo::SvgGroup> groups;
    std::vector<geo::Polyline> as_chained;  // every group in chaining order, for the travel
    glm::dvec2 pen(0.0);
    for (const auto& [kind, name] : kKinds) {
        geo::SvgGroup g;
        g.id = name;
        g.width = stroke.width;
        for (geo::Polyline& p : chained)
            if (p.kind == kind) g.paths.push_back(std::move(p));
        as_chained.insert(as_chained.end(), g.paths.begin(), g.paths.end());
        pen = geo::order_nearest_end(g.paths, pen);
        groups.push_back(std::move(g));
    }
    for (int level = 1; level <= ref.sampling.hidden_levels; ++level) {
        geo::SvgGroup g;
        g.id = "hidden-" + std::to_string(level);
        g.width = stroke.width * def.hidden.width_scale;
        g.dash = std::to_string(static_cast<int>(std::lround(def.hidden.dash_px))) + " " +
                 std::to_string(static_cast<int>(std::lround(def.hidden.gap_px)));
        g.dash_offsets = true;
        for (const geo::Polyline& p : hidden)
            if (p.level == level) g.paths.push_back(p);
        if (g.paths.empty()) continue;
        as_chained.insert(as_chained.end(), g.paths.begin(), g.paths.end());
        pen = geo::order_nearest_end(g.paths, pen, false);
        groups.push_back(std::move(g));
    }
    stats.travel_before_px = geo::pen_up_travel(as_chained);
    std::vector<geo::Polyline> as_ordered;
    for (const geo::SvgGroup& g : groups)
        as_ordered.insert(as_ordered.end(), g.paths.begin(), g.paths.end());
    stats.travel_after_px = geo::pen_up_travel(as_ordered);

    // Colours: the ink, or each object's own; a path names its colour only where it differs
    // from its group's (the first object's).
    const std::string first_colour =
        frame.items.empty() ? std::string("#33ff4d")
                            : geo::svg_colour(frame.items[0].color.r, frame.items[0].color.g,
                                              frame.items[0].color.b);
    for (geo::SvgGroup& g : groups) {
        g.stroke = stroke.per_object_colour ? first_colour : stroke.ink;
        if (!stroke.per_object_colour && g.dash_offsets) {
            // Deeper hidden lines fade towards the paper: level 1 at the ink, level 3 halfway.
            const int level = g.paths.front().level;
            const float t = 0.25f * static_cast<float>(level - 1);
            const glm::vec3 c = glm::mix(stroke.ink_rgb, stroke.paper_rgb, t);
            g.stroke = geo::svg_colour(c.r, c.g, c.b);
        }
        if (!stroke.per_object_colour) continue;
        for (const geo::Polyline& p : g.paths) {
            const glm::vec3 c = frame.items[p.instance].color;
            const std::string s = geo::svg_colour(c.r, c.g, c.b);
            g.path_stroke.push_back(s == g.stroke ? std::string() : s);
        }
    }
    if (options.hud && !frame.hud.empty())
        groups.push_back(hud_group(frame, width, height, stroke.width));
    stats.chain_order_ms = ms_since(t0);

    t0 = Clock::now();
    std::string doc = geo::svg_document(width, height, stroke.background, groups);
    stats.write_ms = ms_since(t0);
    if (stats_out) *stats_out = stats;
    return doc;
}

}  // namespace bz::render
