#include "geometry/import/import.h"

#include "geometry/import/import_scene.h"
#include "geometry/import/import_worker.h"

namespace bz::geo {

TriMesh import_model(const std::filesystem::path& path, const ImportOptions& options) {
    return detail::run_isolated(path, options.limits, [&path, &options] {
        return detail::import_in_this_process(path, options);
    });
}

}  // namespace bz::geo
