#pragma once
// How a level's model files are imported, in one place for every command that does it: play
// (and --edit), check, bench, reference and replay verification. The same importer, the same
// limits and the same folders, so that a level `check` passes is a level `play` can load.
#include <string>

#include "geometry/import/import_limits.h"
#include "geometry/mesh.h"
#include "level/level.h"

namespace bz::game {

// The import options for a level's models: the file and everything it refers to must lie in
// the level's folder or the data folder (level.model_folders; the model's own folder when
// the level has none, as a hand-built one).
geo::ImportOptions level_import_options(const level::Level& level);

// Imports the model of a kind = "model" obstacle and builds its line mesh. Throws UserError
// "LEVEL:LINE:COL: error: model MODEL: REASON" naming the obstacle that names the model.
geo::AdjacencyMesh import_level_model(const level::Level& level, const level::ObjectDesc& object);

}  // namespace bz::game
