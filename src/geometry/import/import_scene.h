#pragma once
// The import itself, in the calling process: the checks before Assimp (regular file, size,
// declared counts, zip sizes, glTF node instances, confinement), Assimp through the confined
// IOSystem, and the walk that places every node's meshes. import_model runs this in a child
// process; the fuzz target and the child call it directly.
#include <filesystem>

#include "geometry/import/import_limits.h"
#include "geometry/mesh.h"

namespace bz::geo::detail {

// Throws bz::UserError "PATH: error: REASON" (one line) when the file cannot be used.
TriMesh import_in_this_process(const std::filesystem::path& path, const ImportOptions& options);

}  // namespace bz::geo::detail
