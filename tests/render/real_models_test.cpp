// Real models nobody here made render non-empty line masks through the full pipeline, and the
// colour frames are written to build/test-out for a person to look at.
#include <gtest/gtest.h>

#include <filesystem>

#include "render/camera_framing.h"
#include "geometry/import.h"
#include "render/render_fixture.h"

using bz::test::RenderTest;

namespace {
const char* const kModels[] = {
    "/usr/share/assimp/models/PLY/Wuson.ply",
    "/usr/share/assimp/models/OBJ/spider.obj",
    "/usr/share/assimp/models/Collada/duck.dae",
    "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf",
};
}  // namespace

TEST_F(RenderTest, RealModelsRenderNonEmptyMasks) {
    for (const char* path : kModels) {
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path)) << "install assimp-testmodels (tools/install-deps)";
        frame.items.clear();
        const bz::geo::TriMesh tri = bz::geo::import_model(path);
        const auto id = add_mesh(path, tri);
        add_item(id);
        frame.camera = bz::render::frame_bounds(meshes.bounds(id), 50.0, double(kWidth) / kHeight);
        const std::string name = std::filesystem::path(path).stem().string();
        const auto m = mask(name);
        // A recognisable drawing, not a speck: lines across a good part of the frame.
        EXPECT_GT(m.count(), 400);
        save_color(name);
    }
}
