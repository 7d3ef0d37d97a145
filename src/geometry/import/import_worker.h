#pragma once
// Runs an import in a forked child process, so that whatever the importer does with a hostile
// file stays there: the memory cap is set in the child before it allocates anything (and its
// resident size is watched, which also works under AddressSanitizer, whose own mappings do
// not fit under a data-segment cap); an import that has used too much CPU time is abandoned,
// and so is one still unfinished at a wall-clock backstop (blocked, or starved on a busy
// machine); a crash (Assimp's SIGABRT on a zip bomb, a stack overflow) becomes a message. The
// child sends the triangle list back over a pipe. The parent never blocks past the backstop.
#include <filesystem>
#include <functional>

#include "geometry/import/import_limits.h"
#include "geometry/mesh.h"

namespace bz::geo::detail {

// Runs `work` in a child process under `limits` (memory_bytes, seconds, max_triangles) and
// returns its mesh. Throws bz::UserError "PATH: error: REASON" with the child's own UserError
// message, or with why the child was abandoned (time, memory, a signal).
TriMesh run_isolated(const std::filesystem::path& path, const ImportLimits& limits,
                     const std::function<TriMesh()>& work);

}  // namespace bz::geo::detail
