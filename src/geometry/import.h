#pragma once
// Loading model files (every format Assimp reads) into one triangle list.
#include <cstdint>
#include <filesystem>

#include "geometry/mesh.h"

namespace bz::geo {

// Largest model file import_model accepts.
inline constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{512} << 20;

// Reads a model, triangulated, with every node's mesh instances placed by the node transforms
// (a mesh that several nodes reference appears once per node). Points and lines are dropped.
// Positions stay in the file's own units and origin: no re-centring or rescaling.
// Throws bz::UserError with one line "FILE: error: REASON" when the file is missing, not a
// regular file, over kMaxModelFileBytes, rejected by Assimp, has no triangles or has a
// non-finite position.
TriMesh import_model(const std::filesystem::path& path);

}  // namespace bz::geo
