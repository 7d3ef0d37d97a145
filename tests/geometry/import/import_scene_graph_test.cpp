// Scene graphs whose nodes are shared by several parents (a DAG: instances double per level)
// or form a cycle are refused by counting node instances with a budget before Assimp copies
// them; ordinary instancing still loads.
#include <gtest/gtest.h>

#include <chrono>

#include "geometry/import/import_gltf.h"
#include "gltf_test_files.h"
#include "import_test_util.h"

namespace bz::geo {
namespace {

using namespace test;  // ScratchDir, import_error, expect_refusal, quick, seconds_since

TEST(SceneGraph, GlbWithFortyLevelDagIsRefusedAtOnce) {
    ScratchDir dir;
    const std::string json =
        test::gltf_json(R"({"byteLength": 42})", test::dag_nodes(40), "[0, 1]");
    const auto p = dir.write("dag.glb", test::glb(json));
    ASSERT_LT(std::filesystem::file_size(p), 4096u);
    const auto start = Clock::now();
    expect_refusal(import_error(p, quick()), p, "node instances");
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(SceneGraph, GltfTextDagIsRefusedToo) {
    ScratchDir dir;
    dir.write("tri.bin", test::triangle_buffer());
    const auto p = dir.write("dag.gltf", test::gltf_json(R"({"uri": "tri.bin", "byteLength": 42})",
                                                         test::dag_nodes(30), "[0]"));
    expect_refusal(import_error(p, quick()), p, "node instances");
}

TEST(SceneGraph, NodeThatIsItsOwnAncestorIsRefused) {
    ScratchDir dir;
    const std::string nodes =
        R"([{"children": [1]}, {"children": [2]}, {"children": [0], "mesh": 0}])";
    const auto p =
        dir.write("cycle.glb", test::glb(test::gltf_json(R"({"byteLength": 42})", nodes, "[0]")));
    expect_refusal(import_error(p, quick()), p, "is its own ancestor");
}

TEST(SceneGraph, SmallDagWithinTheBudgetLoadsEveryInstance) {
    ScratchDir dir;
    // 4 levels: 2 roots x 2 x 2 x 2 paths reach the meshes = 16 triangles.
    const auto p = dir.write(
        "small_dag.glb",
        test::glb(test::gltf_json(R"({"byteLength": 42})", test::dag_nodes(4), "[0, 1]")));
    EXPECT_EQ(import_model(p, quick()).triangle_count(), 16u);
}

TEST(SceneGraph, BudgetCountsInstancesNotNodes) {
    const std::string json =
        test::gltf_json(R"({"byteLength": 42})", test::dag_nodes(10), "[0, 1]");
    // 20 nodes but 2 + 4 + ... + 1024 = 2046 instances.
    EXPECT_FALSE(detail::gltf_nodes_over_limit(json, 2046));
    EXPECT_TRUE(detail::gltf_nodes_over_limit(json, 2045));
}

TEST(SceneGraph, DeeplyNestedJsonIsRefusedWithoutRecursing) {
    const std::string json =
        "{\"nodes\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
    const auto why = detail::gltf_nodes_over_limit(json, 1000);
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("levels deep"), std::string::npos);
}

TEST(SceneGraph, WalkBudgetAlsoAppliesAfterImport) {
    // A plain tree (no sharing) of 1 + 3 nodes: a budget of 3 instances is too small.
    ScratchDir dir;
    const std::string nodes = R"([{"children": [1, 2, 3]}, {"mesh": 0}, {"mesh": 0}, {"mesh": 0}])";
    const auto p =
        dir.write("tree.glb", test::glb(test::gltf_json(R"({"byteLength": 42})", nodes, "[0]")));
    ImportOptions o = quick();
    o.limits.max_node_instances = 3;
    expect_refusal(import_error(p, o), p, "node instances");
    o.limits.max_node_instances = 10;
    EXPECT_EQ(import_model(p, o).triangle_count(), 3u);
}

}  // namespace
}  // namespace bz::geo
