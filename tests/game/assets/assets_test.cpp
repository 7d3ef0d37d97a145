// Meshes and the kind -> factory table: every built-in obstacle kind builds, models are shared
// between instances, the game's own models are closed solids, the horizon is complete.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/error.h"
#include "game/assets/backdrop.h"
#include "game/assets/models.h"
#include "game/assets/obstacle_factories.h"
#include "game/test_world.h"
#include "geometry/line_mesh/line_mesh.h"
#include "level/kinds.h"
#include "scene/shapes.h"
#include "support/tree_paths.h"

namespace bz::game {
namespace {

TEST(Assets, FactoryTableBuildsEveryBuiltinKind) {
    scene::MeshLibrary lib;
    const scene::FactoryTable table = make_obstacle_factories(lib);
    int built = 0;
    for (const level::BuiltinKind& k : level::builtin_kinds()) {
        ASSERT_TRUE(table.contains(k.name)) << k.name;
        if (k.shape == level::KindShape::model) continue;
        scene::Placement p;
        p.kind = std::string(k.name);
        p.position = {3, 0, 4};
        p.heading_deg = 90;
        p.scale = 2;
        const scene::Entity e = table.create(p);
        EXPECT_EQ(e.behaviour, scene::Behaviour::obstacle);
        EXPECT_EQ(lib.name(e.mesh), "builtin:" + std::string(k.name));
        if (k.collision_radius > 0.0) {
            EXPECT_EQ(e.collider.shape, scene::ColliderShape::circle) << k.name;
            EXPECT_DOUBLE_EQ(e.collider.radius, k.collision_radius);
        } else {
            EXPECT_EQ(e.collider.shape, scene::ColliderShape::box) << k.name;
            EXPECT_DOUBLE_EQ(e.collider.half_extent.x, k.half_x);
            EXPECT_DOUBLE_EQ(e.collider.half_extent.y, k.half_z);
        }
        EXPECT_DOUBLE_EQ(e.collider.height, k.height);
        EXPECT_DOUBLE_EQ(e.transform.scale, 2.0);
        EXPECT_NEAR(e.transform.yaw, 3.14159265358979 / 2, 1e-12);
        // The mesh matches the kind's size.
        const geo::Bounds& b = lib.bounds(e.mesh);
        EXPECT_NEAR(b.max.x, k.half_x, 1e-5);
        EXPECT_NEAR(b.max.z, k.half_z, 1e-5);
        EXPECT_NEAR(b.max.y, k.height, 1e-5);
        EXPECT_NEAR(b.min.y, 0.0, 1e-6);
        ++built;
    }
    EXPECT_GE(built, 3);
}

TEST(Assets, ModelKindImportsOnceAndSharesTheMesh) {
    scene::MeshLibrary lib;
    const scene::FactoryTable table = make_obstacle_factories(lib);
    const std::size_t before = lib.size();
    scene::Placement p;
    p.kind = "model";
    p.model = (bz::test::source_dir() / "data/models/pylon.obj").string();
    const scene::Entity a = table.create(p);
    p.position = {50, 0, 0};
    const scene::Entity b = table.create(p);
    EXPECT_EQ(a.mesh, b.mesh);
    EXPECT_EQ(lib.size(), before + 1);
    EXPECT_GT(a.collider.height, 0.0);
    EXPECT_GT(a.collider.half_extent.x, 0.0);
    p.model = "/nonexistent/model.obj";
    EXPECT_THROW(table.create(p), UserError);
}

TEST(Assets, GameModelsAreClosedSolids) {
    std::vector<std::pair<const char*, geo::TriMesh>> meshes = {
        {"slow_tank", models::slow_tank()}, {"super_tank", models::super_tank()},
        {"missile", models::missile()},     {"saucer", models::saucer()},
        {"shell", models::shell()},         {"spark", models::spark()}};
    int i = 0;
    for (const geo::TriMesh& d : models::debris()) meshes.push_back({"debris", d}), ++i;
    EXPECT_GE(i, 3);
    for (const auto& [name, mesh] : meshes) {
        geo::MeshReport report;
        const geo::AdjacencyMesh adj = geo::build_line_mesh(mesh, &report);
        EXPECT_EQ(report.boundary_edges, 0u) << name;
        EXPECT_EQ(report.non_manifold_edges, 0u) << name;
        EXPECT_EQ(report.inconsistent_edges, 0u) << name;
        EXPECT_EQ(report.degenerate_removed, 0u) << name;
        EXPECT_GT(scene::shapes::signed_volume(mesh), 0.0) << name << " faces outwards";
        EXPECT_GT(adj.triangle_count(), 0u);
    }
    // Tanks face -z: the barrel reaches further forward than the hull's back.
    const geo::Bounds tank = geo::compute_bounds(models::slow_tank().positions);
    EXPECT_LT(tank.min.z, -2.5f);
    EXPECT_LT(tank.max.z, 2.5f);
    EXPECT_NEAR(tank.min.y, 0.0f, 1e-6f);
}

// The 1980 arcade's four shapes: closed solids in the proportions their sources give (base
// width : height, see level/kinds.h), blocking within the ROM table's collision radii.
TEST(Assets, ArcadeKindsAreClosedInTheirProportions) {
    struct Expect {
        const char* name;
        bool pyramid;
        double width, depth, height, collision_radius;
    };
    const Expect expected[] = {
        {"arcade_wide_pyramid", true, 7.92, 7.92, 4.56, 4.0},
        {"arcade_narrow_pyramid", true, 4.32, 5.04, 6.0, 3.25},
        {"arcade_tall_box", false, 3.6, 3.6, 9.2, 3.25},
        {"arcade_short_box", false, 4.8, 4.8, 5.6, 3.75},
    };
    for (const Expect& x : expected) {
        const level::BuiltinKind* k = level::find_kind(x.name);
        ASSERT_NE(k, nullptr) << x.name;
        EXPECT_EQ(k->shape, x.pyramid ? level::KindShape::pyramid : level::KindShape::box);
        EXPECT_DOUBLE_EQ(k->collision_radius, x.collision_radius) << x.name;
        const geo::TriMesh mesh = models::obstacle(*k);
        geo::MeshReport report;
        geo::build_line_mesh(mesh, &report);
        EXPECT_EQ(report.boundary_edges, 0u) << x.name;
        EXPECT_EQ(report.non_manifold_edges, 0u) << x.name;
        EXPECT_EQ(report.inconsistent_edges, 0u) << x.name;
        EXPECT_GT(scene::shapes::signed_volume(mesh), 0.0) << x.name << " faces outwards";
        const geo::Bounds b = geo::compute_bounds(mesh.positions);
        const double w = b.max.x - b.min.x;
        const double d = b.max.z - b.min.z;
        const double h = b.max.y - b.min.y;
        EXPECT_NEAR(w / h, x.width / x.height, 1e-5) << x.name;
        EXPECT_NEAR(d / h, x.depth / x.height, 1e-5) << x.name;
        EXPECT_NEAR(h, x.height, 1e-5) << x.name;
        // A pyramid's apex is one point over the middle of the base; a box's top is its base.
        std::size_t at_top = 0;
        for (const glm::vec3& p : mesh.positions) {
            if (std::abs(p.y - b.max.y) < 1e-5f) {
                ++at_top;
                if (x.pyramid) {
                    EXPECT_NEAR(p.x, 0.0f, 1e-5f) << x.name;
                    EXPECT_NEAR(p.z, 0.0f, 1e-5f) << x.name;
                }
            }
        }
        EXPECT_GE(at_top, 1u) << x.name;
        if (!x.pyramid) {
            EXPECT_GE(at_top, 4u) << x.name;
        }
    }
    // The wide pyramid is wider than high, the narrow one higher than wide, the tall box more
    // than twice as high as wide, the short box about as high as wide.
    const auto ratio = [](const char* name) {
        const level::BuiltinKind& k = *level::find_kind(name);
        return 2.0 * k.half_x / k.height;
    };
    EXPECT_GT(ratio("arcade_wide_pyramid"), 1.5);
    EXPECT_LT(ratio("arcade_narrow_pyramid"), 1.0);
    EXPECT_LT(ratio("arcade_tall_box"), 0.5);
    EXPECT_NEAR(ratio("arcade_short_box"), 0.86, 0.01);
}

TEST(Assets, HorizonOutlinesAreOpenStrips) {
    for (const auto& [name, mesh] :
         {std::pair{"mountains", backdrop::mountains({})},
          std::pair{"volcano", backdrop::volcano()}, std::pair{"moon", backdrop::moon()}}) {
        geo::MeshReport report;
        geo::build_line_mesh(mesh, &report);
        EXPECT_GT(report.boundary_edges, 0u) << name << ": its outline is its boundary";
        EXPECT_EQ(report.non_manifold_edges, 0u) << name;
        EXPECT_EQ(report.inconsistent_edges, 0u) << name;
        EXPECT_EQ(report.degenerate_removed, 0u) << name;
    }
    // The mountain ring closes: its boundary is two loops (horizon and silhouette) with as many
    // edges as quads on each.
    const geo::TriMesh m = backdrop::mountains({{0, 2}, {120, 5}, {240, 3}});
    geo::MeshReport report;
    geo::build_line_mesh(m, &report);
    EXPECT_EQ(report.boundary_edges, m.triangle_count());
    // Every triangle faces the centre.
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]];
        const glm::vec3 n =
            glm::cross(m.positions[m.indices[t + 1]] - a, m.positions[m.indices[t + 2]] - a);
        ASSERT_LT(glm::dot(n, a), 0.0f);
    }
}

TEST(Assets, OneMeshPerModelHoweverManyInstances) {
    level::Level lv = test::empty_level();
    for (int i = 0; i < 30; ++i)
        lv.obstacles.push_back(test::object("cube", -60.0 + 4.0 * i, -30.0));
    const Assets& a = test::shared_assets();
    const std::size_t meshes_before = a.meshes().size();
    World w(lv, 1, a.factories(), a.models());
    w.spawn_hostile(HostileKind::slow_tank, {0, 20});
    const scene::FrameList f = w.interpolated_frame(1.0);
    std::set<scene::MeshId> cube_meshes;
    for (const scene::DrawItem& item : f.items) {
        if (a.meshes().name(item.mesh) == "builtin:cube") cube_meshes.insert(item.mesh);
    }
    EXPECT_EQ(cube_meshes.size(), 1u);
    EXPECT_EQ(f.items.size(), 31u);
    EXPECT_EQ(a.meshes().size(), meshes_before) << "no per-instance meshes";
}

TEST(Assets, LevelWithUnknownKindNamesItsPosition) {
    level::Level lv = test::empty_level();
    level::ObjectDesc o = test::object("blob", 1, 1);
    o.pos = {"lv.toml", 12, 3};
    lv.obstacles.push_back(o);
    try {
        test::make_world(lv);
        FAIL();
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("lv.toml:12:3: error: unknown object kind 'blob'", 0),
                  0u)
            << e.what();
    }
}

TEST(Assets, BackdropItemsFollowTheEye) {
    level::Backdrop b;
    b.volcano = true;
    b.moon = true;
    const Assets& a = test::shared_assets();
    std::vector<scene::DrawItem> items;
    backdrop::append_items(items, b, a.horizon(), {100, 1.4, -50}, 1.0);
    std::set<scene::MeshId> ids;
    int sparks = 0;
    for (const auto& it : items) {
        ids.insert(it.mesh);
        sparks += it.mesh == a.horizon().spark;
    }
    EXPECT_TRUE(ids.count(a.horizon().mountains));
    EXPECT_TRUE(ids.count(a.horizon().volcano));
    EXPECT_TRUE(ids.count(a.horizon().moon));
    EXPECT_GT(sparks, 0) << "the volcano is erupting";
    // The mountain ring is centred on the eye, on the ground.
    EXPECT_EQ(items[0].model[3][0], 100.0);
    EXPECT_EQ(items[0].model[3][2], -50.0);
    // Ejecta move over time.
    std::vector<scene::DrawItem> later;
    backdrop::append_items(later, b, a.horizon(), {100, 1.4, -50}, 1.3);
    bool moved = false;
    for (std::size_t i = 0; i < std::min(items.size(), later.size()); ++i) {
        if (items[i].mesh == a.horizon().spark && items[i].model != later[i].model) moved = true;
    }
    EXPECT_TRUE(moved);
    // The moon stands where the level says: azimuth 300 is left of straight ahead (-z).
    for (const auto& it : items) {
        if (it.mesh != a.horizon().moon) continue;
        const glm::dvec3 p = glm::dvec3(it.model[3]) - glm::dvec3(100, 0, -50);
        EXPECT_LT(p.x, 0.0);
        EXPECT_LT(p.z, 0.0);
        EXPECT_NEAR(std::atan2(p.y, std::hypot(p.x, p.z)) * 180 / 3.14159265, b.moon_elevation_deg,
                    0.01);
        // Its face (+z) points back at the eye.
        const glm::dvec3 n = glm::normalize(glm::dvec3(it.model * glm::dvec4(0, 0, 1, 0)));
        EXPECT_LT(glm::dot(n, glm::normalize(p)), -0.99);
    }
}

}  // namespace
}  // namespace bz::game
