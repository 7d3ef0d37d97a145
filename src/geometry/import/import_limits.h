#pragma once
// What a model import may use and where it may read from. Every command that imports a model
// (render, reference, bench, check, play) goes through geo::import_model with these limits,
// set before the importer allocates anything.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/budgets.h"

namespace bz::geo {

struct ImportLimits {
    // Largest model file, and largest file it references (.mtl, glTF buffers, ...).
    std::uintmax_t max_file_bytes = budget::kModelBytes;
    // Memory of the import process (the data segment, and its resident size for sanitizer
    // builds): BEAMZONE_MEMORY_LIMIT_MB, default 8192; 0 = no cap.
    std::uint64_t memory_bytes = std::uint64_t{8192} << 20;
    // CPU time after which an import is abandoned: an importer that spins. CPU time rather
    // than wall-clock time, so that a busy machine (a parallel build, a test run) does not
    // refuse a model that imports in milliseconds when the import gets no CPU for a while.
    double seconds = 10.0;
    // Wall-clock time after which an import that is neither finishing nor using that CPU
    // time (blocked, or starved) is abandoned all the same.
    double wall_seconds = 60.0;
    // Sum of the uncompressed sizes of a zip-based file's entries (.3mf, .zae, .pk3, ...).
    std::uint64_t max_unzipped_bytes = std::uint64_t{256} << 20;
    // Node instances reached walking the scene graph from its roots: a node that several
    // parents share counts once per path, as importers copy it once per path.
    std::uint64_t max_node_instances = std::uint64_t{1} << 17;
    // Triangles and vertices after every node instance is placed (keeps indices in 32 bits
    // and the line mesh build within memory).
    std::size_t max_triangles = std::size_t{1} << 27;
    // Lines of a text format without declared counts (OBJ).
    std::uint64_t max_text_lines = std::uint64_t{1} << 26;
};

// The limits with the memory cap taken from BEAMZONE_MEMORY_LIMIT_MB when it is set.
ImportLimits default_import_limits();

struct ImportOptions {
    // Folders (canonical) that the model and every file it references must lie in, after
    // resolving `..` and symbolic links. Empty: the model's own folder.
    std::vector<std::filesystem::path> allowed_folders;
    ImportLimits limits = default_import_limits();
};

}  // namespace bz::geo
