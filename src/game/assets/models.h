#pragma once
// The game's own models as triangle meshes, facing -z with their base on y = 0 (shells and
// debris are centred on their origin). Sizes in world units; see tuning.h for colliders.
#include <vector>

#include "geometry/mesh.h"
#include "level/kinds.h"

namespace bz::game::models {

geo::TriMesh slow_tank();            // wedge hull, turret, barrel, radar dish
geo::TriMesh super_tank();           // lower, longer and sleeker
geo::TriMesh missile();              // body, nose cone and tail fins
geo::TriMesh saucer();               // two shallow cones and a dome
geo::TriMesh shell();                // a small diamond
geo::TriMesh spark();                // volcano ejecta, sized for the horizon
std::vector<geo::TriMesh> debris();  // assorted wreckage pieces

// A built-in obstacle kind's block or pyramid at scale 1 (not for KindShape::model).
geo::TriMesh obstacle(const level::BuiltinKind& kind);

}  // namespace bz::game::models
