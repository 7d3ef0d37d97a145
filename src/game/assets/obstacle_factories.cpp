#include "game/assets/obstacle_factories.h"

#include <algorithm>
#include <cmath>

#include "game/assets/models.h"
#include "geometry/import/import.h"
#include "geometry/line_mesh/line_mesh.h"
#include "level/kinds.h"

namespace bz::game {

namespace {

scene::Entity place(const scene::Placement& p, scene::MeshId mesh, scene::Collider collider) {
    scene::Entity e;
    e.mesh = mesh;
    e.behaviour = scene::Behaviour::obstacle;
    e.collider = collider;
    e.color = p.color;
    e.transform.position = p.position;
    e.transform.yaw = p.heading_deg * 3.14159265358979323846 / 180.0;
    e.transform.scale = p.scale;
    return e;
}

}  // namespace

scene::FactoryTable make_obstacle_factories(scene::MeshLibrary& library) {
    scene::FactoryTable table;
    for (const level::BuiltinKind& kind : level::builtin_kinds()) {
        if (kind.shape == level::KindShape::model) continue;
        const scene::MeshId mesh = library.add("builtin:" + std::string(kind.name),
                                               geo::build_line_mesh(models::obstacle(kind)));
        // Pyramids block like their base: a tank cannot drive up their slopes either. The
        // arcade's kinds block within their ROM collision radius instead.
        const scene::Collider collider =
            kind.collision_radius > 0.0
                ? scene::Collider{scene::ColliderShape::circle,
                                  kind.collision_radius,
                                  {},
                                  kind.height}
                : scene::Collider{
                      scene::ColliderShape::box, 0.0, {kind.half_x, kind.half_z}, kind.height};
        table.add(std::string(kind.name),
                  [mesh, collider](const scene::Placement& p) { return place(p, mesh, collider); });
    }
    scene::MeshLibrary* lib = &library;
    table.add("model", [lib](const scene::Placement& p) {
        const std::string name = p.model.string();
        scene::MeshId mesh = 0;
        if (auto found = lib->find(name)) {
            mesh = *found;
        } else {
            mesh = lib->add(name, geo::build_line_mesh(geo::import_model(p.model)));
        }
        // The footprint is the mesh's own bounds on the ground plane.
        const geo::Bounds& b = lib->bounds(mesh);
        const glm::dvec2 half{std::max(std::abs(b.min.x), std::abs(b.max.x)),
                              std::max(std::abs(b.min.z), std::abs(b.max.z))};
        const scene::Collider collider{scene::ColliderShape::box, 0.0, half,
                                       std::max(0.0f, b.max.y)};
        return place(p, mesh, collider);
    });
    return table;
}

}  // namespace bz::game
