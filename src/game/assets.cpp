#include "game/assets.h"

#include "game/models.h"
#include "game/obstacle_factories.h"
#include "geometry/line_mesh.h"

namespace bz::game {

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

}  // namespace bz::game
