#pragma once
// Visible line segments joined into polylines, as a plotter or an SVG editor wants them: one
// path per run of segments that meet end to end, instead of one per piece of feature edge.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "geometry/reference/reference.h"

namespace bz::geo {

struct Polyline {
    std::vector<glm::dvec2> points;  // at least two; a closed loop repeats its first point
    LineKind kind = LineKind::crease;
    std::uint32_t instance = 0;
    std::uint8_t level = 0;    // occlusion level (VisibleSegment::level)
    double dash_offset = 0.0;  // a dash pattern's phase at the first point (single segments)
};

// Joins segments of the same kind, instance and occlusion level whose ends lie within `tolerance`
// of each other (in the segments' units) into polylines; where three or more segments meet, a
// polyline ends. Ends closer than the tolerance are merged to the first one seen, so no point moves
// further than `tolerance`. Every segment appears in exactly one polyline. Deterministic: the
// result depends only on the segments' order and values. Throws std::invalid_argument for a
// tolerance that is negative or not finite.
std::vector<Polyline> chain_segments(std::span<const VisibleSegment> segments, double tolerance);

// One polyline per segment, as found (a to b), with the segment's edge offset as its dash
// offset: for dashed lines, whose pattern must stay fixed to the edge.
std::vector<Polyline> single_segments(std::span<const VisibleSegment> segments);

}  // namespace bz::geo
