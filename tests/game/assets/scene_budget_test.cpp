// The scene budget: a level over the object, triangle or GPU memory budget is refused with the
// level line of the object that crosses it; a level within them passes with its cost counted.
#include "game/assets/scene_budget.h"

#include <gtest/gtest.h>

#include <string>

#include "core/budgets.h"
#include "core/error.h"
#include "game/assets/models.h"
#include "level/kinds.h"

namespace {

bz::level::ObjectDesc object(const std::string& model, int line) {
    bz::level::ObjectDesc o;
    o.kind = model.empty() ? "cube" : "model";
    o.model = model;
    o.pos.file = "big.toml";
    o.pos.line = line;
    o.pos.column = 1;
    return o;
}

// The message of check_scene_budget's refusal, or "" when it passes.
std::string refusal(const bz::level::Level& level, const std::map<std::string, std::int64_t>& t) {
    try {
        bz::game::check_scene_budget(level, t);
    } catch (const bz::UserError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(SceneBudget, ALevelWithinTheBudgetsPassesWithItsCost) {
    bz::level::Level level;
    for (int i = 0; i < 10; ++i) level.obstacles.push_back(object("tank.obj", 10 + i));
    level.obstacles.push_back(object("", 30));
    const auto cost = bz::game::check_scene_budget(level, {{"tank.obj", 1000}});
    const std::int64_t cube = static_cast<std::int64_t>(
        bz::game::models::obstacle(*bz::level::find_kind("cube")).triangle_count());
    EXPECT_EQ(cost.instances, 11);
    EXPECT_EQ(cost.triangles, 10000 + cube);
    // One model mesh and one cube mesh, each shared by its copies.
    EXPECT_EQ(cost.gpu_bytes, (1000 + cube) * bz::budget::kGpuBytesPerTriangle);
}

// Every built-in kind counts the triangles of its own mesh, once per placed copy: a level of
// built-in obstacles alone has a triangle cost, and one that fills the budget with a model
// is refused at the built-in obstacle that crosses it.
TEST(SceneBudget, BuiltInObstaclesCountTheirMeshesTriangles) {
    bz::level::Level level;
    std::int64_t expected = 0;
    int line = 10;
    for (const bz::level::BuiltinKind& kind : bz::level::builtin_kinds()) {
        if (kind.shape == bz::level::KindShape::model) continue;
        const auto tris =
            static_cast<std::int64_t>(bz::game::models::obstacle(kind).triangle_count());
        ASSERT_GT(tris, 0) << kind.name;
        for (int copy = 0; copy < 3; ++copy) {
            bz::level::ObjectDesc o = object("", line++);
            o.kind = std::string(kind.name);
            level.obstacles.push_back(o);
            expected += tris;
        }
    }
    const auto cost = bz::game::check_scene_budget(level, {});
    EXPECT_EQ(cost.triangles, expected);
    EXPECT_GT(cost.gpu_bytes, 0);

    // Copies of a model that fill the triangle budget exactly; one cube more crosses it.
    bz::level::Level full;
    const std::int64_t per_copy = 1'000'000;
    const int copies = static_cast<int>(bz::budget::kSceneTriangles / per_copy);
    for (int i = 0; i < copies; ++i) full.obstacles.push_back(object("m.obj", 100 + i));
    ASSERT_EQ(refusal(full, {{"m.obj", per_copy}}), "");
    full.obstacles.push_back(object("", 100 + copies));  // a cube
    const std::string why = refusal(full, {{"m.obj", per_copy}});
    EXPECT_NE(why.find("big.toml:" + std::to_string(100 + copies) + ":1: error"), std::string::npos)
        << why;
    EXPECT_NE(why.find("triangles"), std::string::npos) << why;
}

TEST(SceneBudget, EachBudgetNamesTheLineThatCrossesIt) {
    struct Case {
        const char* what;
        std::int64_t model_triangles;
        int copies;
        int crossing_copy;  // 1-based
        const char* needle;
    };
    const std::int64_t t = 5'000'000;
    const Case cases[] = {
        // 5,000 copies of a 5M-triangle model: the 11th makes 55M > 50M.
        {"triangles", t, 5000, static_cast<int>(bz::budget::kSceneTriangles / t) + 1, "triangles"},
        // Objects alone: one past the instance budget.
        {"instances", 0, static_cast<int>(bz::budget::kSceneInstances) + 5,
         static_cast<int>(bz::budget::kSceneInstances) + 1, "objects"},
    };
    for (const Case& c : cases) {
        bz::level::Level level;
        for (int i = 0; i < c.copies; ++i) level.obstacles.push_back(object("m.obj", 100 + i));
        const std::string why = refusal(level, {{"m.obj", c.model_triangles}});
        EXPECT_NE(why.find("big.toml:" + std::to_string(100 + c.crossing_copy - 1) + ":1: error"),
                  std::string::npos)
            << c.what << ": " << why;
        EXPECT_NE(why.find(c.needle), std::string::npos) << why;
    }
    // GPU memory: distinct meshes, each counted once however often it is placed.
    bz::level::Level level;
    std::map<std::string, std::int64_t> tris;
    const std::int64_t per_mesh = bz::budget::kSceneGpuBytes / bz::budget::kGpuBytesPerTriangle / 3;
    for (int i = 0; i < 4; ++i) {
        const std::string name = "m" + std::to_string(i) + ".obj";
        tris[name] = per_mesh;
        level.obstacles.push_back(object(name, 200 + i));
    }
    const std::string why = refusal(level, tris);
    EXPECT_NE(why.find("big.toml:203:1: error"), std::string::npos) << why;
    EXPECT_NE(why.find("GPU memory"), std::string::npos) << why;
}
