#include "app/model_source.h"

#include "core/error.h"
#include "core/text/printable.h"
#include "game/assets/models.h"
#include "geometry/generated/primitives.h"
#include "geometry/import/import.h"

namespace bz::app {

geo::TriMesh load_model_source(const std::string& input) {
    const std::string prefix = "builtin:";
    if (input.rfind(prefix, 0) != 0) return geo::import_model(input);
    const std::string name = input.substr(prefix.size());
    if (name == "cube") return geo::box(glm::vec3(0.5f));
    if (name == "sphere") return geo::uv_sphere(1.0f, 32, 64);
    // 6 bands x 8 segments: visibly polygonal, for the halo style's cubic smoothing.
    if (name == "coarse-sphere") return geo::uv_sphere(1.0f, 6, 8);
    // 708 x 708 cells x 2 = 1,002,528 triangles, seams every 16 cells.
    if (name == "grid") return geo::grid(708, 708, 0.01f, 16);
    if (name == "grid-100k") return geo::grid(224, 224, 0.03f, 16);
    // The game's enemy tank: the desktop icon is rendered from it (dist/README.md).
    if (name == "tank") return game::models::slow_tank();
    throw UserError(
        printable(input) +
        ": unknown built-in model (cube, sphere, coarse-sphere, grid, grid-100k, tank)");
}

}  // namespace bz::app
