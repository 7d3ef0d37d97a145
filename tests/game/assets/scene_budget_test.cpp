// The scene budget: a level over the object, triangle or GPU memory budget is refused with the
// level line of the object that crosses it; a level within them passes with its cost counted.
#include "game/assets/scene_budget.h"

#include <gtest/gtest.h>

#include <string>

#include "core/budgets.h"
#include "core/error.h"

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
    EXPECT_EQ(cost.instances, 11);
    EXPECT_EQ(cost.triangles, 10000);
    EXPECT_EQ(cost.gpu_bytes, 1000 * bz::budget::kGpuBytesPerTriangle);  // one mesh, shared
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
