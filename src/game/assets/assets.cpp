#include "game/assets/assets.h"

#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/text/printable.h"
#include "game/assets/level_models.h"
#include "game/assets/models.h"
#include "game/assets/obstacle_factories.h"
#include "game/assets/scene_budget.h"
#include "geometry/line_mesh/line_mesh.h"
#include "level/diagnostic.h"

namespace bz::game {

namespace {

bool same_geometry(const geo::AdjacencyMesh& a, const geo::AdjacencyMesh& b) {
    return a.positions == b.positions && a.triangles == b.triangles && a.adjacency == b.adjacency &&
           a.edge_kinds == b.edge_kinds;
}

}  // namespace

Assets::Assets(const level::Backdrop& b) : library_(std::make_unique<scene::MeshLibrary>()) {
    scene::MeshLibrary& lib = *library_;
    auto add = [&lib](const std::string& name, const geo::TriMesh& mesh) {
        return lib.add(name, geo::build_line_mesh(mesh));
    };
    models_.slow_tank = add("game:slow_tank", models::slow_tank());
    models_.super_tank = add("game:super_tank", models::super_tank());
    models_.missile = add("game:missile", models::missile());
    models_.saucer = add("game:saucer", models::saucer());
    models_.shell = add("game:shell", models::shell());
    int i = 0;
    for (const geo::TriMesh& piece : models::debris()) {
        models_.debris.push_back(add("game:debris" + std::to_string(i++), piece));
    }
    horizon_.mountains = add("game:mountains", backdrop::mountains(b.mountains));
    horizon_.volcano = add("game:volcano", backdrop::volcano());
    horizon_.moon = add("game:moon", backdrop::moon());
    horizon_.spark = add("game:spark", models::spark());
    factories_ = make_obstacle_factories(lib);
}

Assets::Assets(const level::Level& level) : Assets(level.backdrop) {
    reload(level);
}

void Assets::reload(const level::Level& level) {
    // Everything is checked and imported before the library changes.
    std::vector<std::pair<std::string, geo::AdjacencyMesh>> changed;
    std::set<std::string> imported;
    std::map<std::string, std::int64_t> triangles;
    for (const level::ObjectDesc& o : level.obstacles) {
        if (!factories_.contains(o.kind)) {
            throw UserError(level::where(o.pos) + "error: no object kind '" + printable(o.kind) +
                            "'");
        }
        if (o.model.empty() || !imported.insert(o.model.string()).second) continue;
        geo::AdjacencyMesh mesh = import_level_model(level, o);
        triangles[o.model.string()] = static_cast<std::int64_t>(mesh.triangle_count());
        const std::optional<scene::MeshId> id = library_->find(o.model.string());
        if (id && same_geometry(library_->mesh(*id), mesh)) continue;
        changed.emplace_back(o.model.string(), std::move(mesh));
    }
    check_scene_budget(level, triangles);  // before anything is uploaded
    geo::AdjacencyMesh mountains =
        geo::build_line_mesh(backdrop::mountains(level.backdrop.mountains));
    if (!same_geometry(library_->mesh(horizon_.mountains), mountains)) {
        changed.emplace_back(library_->name(horizon_.mountains), std::move(mountains));
    }
    for (auto& [name, mesh] : changed) library_->add(name, std::move(mesh));
}

}  // namespace bz::game
