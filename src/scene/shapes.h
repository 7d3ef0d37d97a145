#pragma once
// Small triangle-mesh builders for the game's own models (tanks, missile, saucer, shells,
// debris, the horizon). Closed shapes wind counter-clockwise seen from outside; flat outline
// shapes are open, single-sided strips whose boundary edges draw as lines.
#include <glm/glm.hpp>
#include <vector>

#include "geometry/mesh.h"

namespace bz::scene::shapes {

// A horizontal cross-section for loft(): a convex polygon at height y, counter-clockwise seen
// from above. A ring of one point is an apex.
struct Ring {
    std::vector<glm::vec2> xz;  // (x, z) pairs
    float y = 0.0f;
};

// Joins consecutive rings with quads (all rings but apexes have the same point count) and caps
// the first and last ring when they are not apexes. The result is closed and outward-facing.
geo::TriMesh loft(const std::vector<Ring>& rings);

// A convex polygon ring: `sides` points on an ellipse of radii (rx, rz) centred at `center`.
Ring ellipse_ring(int sides, glm::vec2 radii, float y, glm::vec2 center = {0.0f, 0.0f},
                  float phase = 0.0f);
// A rectangle ring of size (width along x, length along z) centred at `center`.
Ring rect_ring(float width, float length, float y, glm::vec2 center = {0.0f, 0.0f});

// An axis-aligned box from its two corners.
geo::TriMesh box(glm::vec3 min, glm::vec3 max);

// A single-sided strip between two polylines of the same length (`lower[i]` joins `upper[i]`),
// facing the side from which `lower` runs left to right. closed = the last point joins the
// first (a ring).
geo::TriMesh strip(const std::vector<glm::vec3>& lower, const std::vector<glm::vec3>& upper,
                   bool closed);

// Appends `src` transformed by `m` to `dst`.
void append(geo::TriMesh& dst, const geo::TriMesh& src, const glm::mat4& m = glm::mat4(1.0f));

// Signed volume (positive for a closed outward-facing mesh); used by tests and sanity checks.
double signed_volume(const geo::TriMesh& mesh);

}  // namespace bz::scene::shapes
