#include "scene/factory_table.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace bz::scene {
namespace {

TEST(FactoryTable, CreatesByKindAndListsKinds) {
    FactoryTable t;
    t.add("crate", [](const Placement& p) {
        Entity e;
        e.mesh = 7;
        e.transform.position = p.position;
        e.transform.scale = p.scale;
        e.behaviour = Behaviour::obstacle;
        return e;
    });
    t.add("tree", [](const Placement&) { return Entity{}; });
    EXPECT_TRUE(t.contains("crate"));
    EXPECT_FALSE(t.contains("rock"));
    Placement p;
    p.kind = "crate";
    p.position = {1, 0, 2};
    p.scale = 3.0;
    const Entity e = t.create(p);
    EXPECT_EQ(e.mesh, 7u);
    EXPECT_EQ(e.transform.position, glm::dvec3(1, 0, 2));
    EXPECT_EQ(e.transform.scale, 3.0);
    EXPECT_EQ(t.kinds(), (std::vector<std::string>{"crate", "tree"}));
}

TEST(FactoryTable, UnknownKindNamesTheKnownOnes) {
    FactoryTable t;
    t.add("cube", [](const Placement&) { return Entity{}; });
    Placement p;
    p.kind = "cubee";
    try {
        t.create(p);
        FAIL() << "no error";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()), "unknown object kind 'cubee' (known kinds: cube)");
    }
}

TEST(FactoryTable, AddReplaces) {
    FactoryTable t;
    auto with_mesh = [](MeshId id) {
        return [id](const Placement&) {
            Entity e;
            e.mesh = id;
            return e;
        };
    };
    t.add("a", with_mesh(1));
    t.add("a", with_mesh(2));
    Placement p;
    p.kind = "a";
    EXPECT_EQ(t.create(p).mesh, 2u);
    EXPECT_EQ(t.kinds().size(), 1u);
}

TEST(Transform, MatrixFacesForward) {
    Transform t;
    t.position = {10, 0, 5};
    t.yaw = 3.14159265358979 / 2.0;  // a quarter turn left: -z turns to -x
    const glm::dvec4 nose = t.matrix() * glm::dvec4(0, 0, -1, 1);
    EXPECT_NEAR(nose.x, 9.0, 1e-9);
    EXPECT_NEAR(nose.z, 5.0, 1e-9);
    EXPECT_NEAR(t.forward().x, -1.0, 1e-9);
    EXPECT_NEAR(t.forward().z, 0.0, 1e-9);
}

}  // namespace
}  // namespace bz::scene
