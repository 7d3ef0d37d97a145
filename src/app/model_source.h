#pragma once
// Where `render` (and the other headless commands) get a model: a file through Assimp, or a
// generated one by name, so benchmarks need no data files:
//   builtin:cube  builtin:sphere  builtin:grid  (about 1M triangles)  builtin:grid-100k
#include <string>

#include "geometry/mesh.h"

namespace bz::app {

// Throws UserError naming the input when it cannot be used.
geo::TriMesh load_model_source(const std::string& input);

}  // namespace bz::app
