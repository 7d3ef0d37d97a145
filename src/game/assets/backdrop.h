#pragma once
// The 360-degree horizon: mountain silhouettes, an erupting volcano and a crescent moon. They
// sit on a ring far away that moves with the eye, so they never come closer, only turn.
#include <vector>

#include "geometry/mesh.h"
#include "level/level.h"
#include "scene/frame_list.h"

namespace bz::game::backdrop {

inline constexpr double kRadius = 2000.0;

// Azimuth is in degrees clockwise from -z (straight ahead at yaw 0) towards +x, like a compass.
glm::dvec3 direction(double azimuth_deg);

// The mountains as one closed single-sided strip facing the centre: its lower edge is the
// horizon line, its upper edge the silhouette. Points are sorted by azimuth and subdivided so
// the strip bends by at most a few degrees between quads. An empty list gets a default range.
geo::TriMesh mountains(const std::vector<glm::dvec2>& points);
std::vector<glm::dvec2> default_mountains();

// The volcano's cone as an open strip at azimuth 0 (placed by the draw item's rotation).
geo::TriMesh volcano();
// A crescent: the lit limb and the terminator, facing +z, unit radius (scaled when placed).
geo::TriMesh moon();

struct Ids {
    scene::MeshId mountains = 0;
    scene::MeshId volcano = 0;
    scene::MeshId moon = 0;
    scene::MeshId spark = 0;
};

// Appends the horizon's draw items around `eye` at time `seconds` (drives the eruption).
void append_items(std::vector<scene::DrawItem>& out, const level::Backdrop& b, const Ids& ids,
                  const glm::dvec3& eye, double seconds);

}  // namespace bz::game::backdrop
