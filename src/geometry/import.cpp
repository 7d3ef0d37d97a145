#include "geometry/import.h"

#include "geometry/import_scene.h"

namespace bz::geo {

TriMesh import_model(const std::filesystem::path& path, const ImportOptions& options) {
    return detail::import_in_this_process(path, options);
}

}  // namespace bz::geo
