// A level's models go through one importer with the level's folders as the confinement:
// play's assets and check use the same function, a model reading outside the level's
// folders is refused with the obstacle's position, and a hot reload that brings a hostile
// model leaves the running game on its last good level.
#include "game/assets/level_models.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "game/assets/assets.h"
#include "game/game.h"
#include "game/test_world.h"
#include "support/scratch_dir.h"

namespace bz::game {
namespace {

namespace fs = std::filesystem;

struct LevelFolder {
    bz::test::ScratchDir scratch{"bz_level_models"};
    fs::path root = scratch.path();
    fs::path level = root / "level";
    LevelFolder() {
        fs::create_directories(level);
        fs::create_directories(root / "outside");
        std::ofstream(root / "outside" / "secret.mtl") << "newmtl x\nKd 1 0 0\n";
        std::ofstream(level / "good.obj") << "v 0 0 0\nv 2 0 0\nv 0 0 2\nv 0 2 0\n"
                                             "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
        std::ofstream(level / "escape.obj") << "mtllib ../outside/secret.mtl\n"
                                               "v 0 0 0\nv 2 0 0\nv 0 0 2\nf 1 3 2\n";
    }

    level::Level with_model(const char* name) const {
        level::Level lv = test::empty_level();
        lv.model_folders = {fs::canonical(level)};
        level::ObjectDesc m = test::object("model", 30.0, -30.0);
        m.model = level / name;
        m.pos = {(level / "l.toml").string(), 7, 3};
        lv.obstacles.push_back(m);
        return lv;
    }
};

TEST(LevelModels, ModelReadingOutsideTheLevelFoldersIsRefusedWithItsPosition) {
    LevelFolder f;
    const level::Level lv = f.with_model("escape.obj");
    try {
        import_level_model(lv, lv.obstacles[0]);
        FAIL() << "no error";
    } catch (const UserError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind((f.level / "l.toml").string() + ":7:3: error: model " +
                              (f.level / "escape.obj").string() + ": reference '",
                          0),
                  0u)
            << m;
        EXPECT_NE(m.find("secret.mtl': leads outside"), std::string::npos) << m;
    }
    // Play's assets refuse the same level with the same message.
    EXPECT_THROW(Assets{lv}, UserError);
}

TEST(LevelModels, GoodModelImportsTheSameForCheckAndPlay) {
    LevelFolder f;
    const level::Level lv = f.with_model("good.obj");
    const geo::AdjacencyMesh checked = import_level_model(lv, lv.obstacles[0]);
    const Assets assets(lv);
    const auto id = assets.meshes().find(lv.obstacles[0].model.string());
    ASSERT_TRUE(id);
    EXPECT_EQ(assets.meshes().mesh(*id).triangles, checked.triangles);
    EXPECT_EQ(checked.triangle_count(), 4u);
}

TEST(LevelModels, HotReloadWithAHostileModelKeepsTheLastGoodLevel) {
    LevelFolder f;
    ASSERT_EQ(::mkfifo((f.level / "pipe.obj").c_str(), 0600), 0);
    GameOptions o;
    o.attract = false;
    o.seed = 3;
    Game g(f.with_model("good.obj"), o);
    for (int i = 0; i < 30; ++i) g.tick({});
    const std::uint64_t tick = g.world()->state().tick;
    for (const char* bad : {"escape.obj", "pipe.obj"}) {
        SCOPED_TRACE(bad);
        EXPECT_THROW(g.reload_level(f.with_model(bad)), UserError);
        // Still the good model, and the game goes on.
        ASSERT_EQ(g.world()->obstacles().size(), 1u);
        EXPECT_EQ(g.meshes().name(g.world()->obstacles()[0].mesh), (f.level / "good.obj").string());
    }
    g.tick({});
    EXPECT_EQ(g.world()->state().tick, tick + 1);
}

}  // namespace
}  // namespace bz::game
