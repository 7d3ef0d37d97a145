#include "game/assets/level_models.h"

#include "core/error.h"
#include "core/text/printable.h"
#include "geometry/import/import.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::game {

geo::ImportOptions level_import_options(const level::Level& level) {
    geo::ImportOptions options;
    options.allowed_folders = level.model_folders;
    return options;
}

geo::AdjacencyMesh import_level_model(const level::Level& level, const level::ObjectDesc& object) {
    try {
        geo::AdjacencyMesh mesh =
            geo::build_line_mesh(geo::import_model(object.model, level_import_options(level)));
        if (mesh.triangle_count() == 0) {
            throw UserError(printable(object.model.string()) + ": error: no usable triangles");
        }
        return mesh;
    } catch (const UserError& e) {
        // The importer says "MODEL: error: REASON"; the level's position goes in front.
        std::string why = e.what();
        const std::string prefix = printable(object.model.string()) + ": error: ";
        if (why.compare(0, prefix.size(), prefix) == 0) {
            why = "model " + printable(object.model.string()) + ": " + why.substr(prefix.size());
        }
        const level::SourcePos& p = object.pos;
        const std::string where = p.file.empty()
                                      ? std::string()
                                      : printable(p.file) + ":" + std::to_string(p.line) + ":" +
                                            std::to_string(p.column) + ": ";
        throw UserError(where + "error: " + why);
    }
}

}  // namespace bz::game
