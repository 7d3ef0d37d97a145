#pragma once
// Orders polylines to cut a pen plotter's pen-up travel: greedy nearest end, the baseline that
// vpype's `linesort` also starts from. Each path may be drawn in either direction.
#include <span>
#include <vector>

#include "geometry/vector/polylines.h"

namespace bz::geo {

// The pen-up distance of drawing `paths` in this order, from each path's last point to the
// next one's first (the move to the first path is not counted).
double pen_up_travel(std::span<const Polyline> paths);

// Reorders (and reverses where that helps, if `may_reverse`) `paths` in place: from `start`,
// repeatedly draw the path with the nearest unused end, starting at that end (without
// `may_reverse`: the nearest first point; a dashed line keeps its direction, so its pattern
// stays where it is). Returns the pen's final position. A spatial grid keeps this near O(n)
// for paths spread over the picture.
glm::dvec2 order_nearest_end(std::vector<Polyline>& paths, glm::dvec2 start,
                             bool may_reverse = true);

}  // namespace bz::geo
