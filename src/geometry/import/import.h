#pragma once
// Loading model files (every format Assimp reads) into one triangle list. This is the one
// importer every command uses (render, reference, bench, check, play), with the same limits.
#include <cstdint>
#include <filesystem>

#include "geometry/import/import_limits.h"
#include "geometry/mesh.h"

namespace bz::geo {

// Largest model file import_model accepts by default (ImportLimits::max_file_bytes).
inline constexpr std::uintmax_t kMaxModelFileBytes = ImportLimits{}.max_file_bytes;

// Reads a model, triangulated, with every node's mesh instances placed by the node transforms
// (a mesh that several nodes reference appears once per node). Points and lines are dropped.
// Positions stay in the file's own units and origin: no re-centring or rescaling.
//
// The import runs in a child process under options.limits (memory, time) and reads only
// regular files inside options.allowed_folders (see import_limits.h). Before Assimp sees the
// file: its size, the counts its header declares (PLY, OFF, binary STL), its line count
// (OBJ), the uncompressed size of a zip-based file and the node instances of a glTF scene
// graph are checked.
//
// Throws bz::UserError with one line "FILE: error: REASON" when the file is missing, not a
// regular file, over a limit, outside the allowed folders, refers to a file that is, is
// rejected by Assimp, crashes it, takes too long, has no triangles or has a non-finite
// position.
TriMesh import_model(const std::filesystem::path& path, const ImportOptions& options = {});

}  // namespace bz::geo
