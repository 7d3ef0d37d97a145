// The renderer models only what a frame needs: one GPU mesh per model shared by all its
// instances (one instanced draw), uploaded only when something visible uses it; objects
// outside the view frustum culled; far objects drawn from simplified meshes. None of these may
// change what the mask shows beyond the LOD's own simplification.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/reference/mask_score.h"
#include "render/camera/camera_math.h"
#include "render/gpu_scene/batches.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

namespace {

using bz::test::RenderTest;

glm::dmat4 at(double x, double y, double z) {
    return glm::translate(glm::dmat4(1.0), {x, y, z});
}

class SceneModellingTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        settings.lod = false;
        frame.camera.eye = {0.0, 3.0, 12.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 50.0;
        frame.camera.near = 0.1;
        frame.camera.far = 500.0;
    }

    bz::render::FrameBatches batches() const {
        const auto cam = bz::render::camera_matrices(
            frame.camera, static_cast<double>(kWidth) / kHeight, settings.depth);
        return bz::render::build_batches(frame, meshes, cam, settings, kHeight);
    }
};

TEST_F(SceneModellingTest, OneGpuMeshPerModelSharedByItsInstances) {
    const auto cube = add_mesh("cube", bz::geo::box(glm::vec3(0.3f)));
    const auto ball = add_mesh("ball", bz::geo::uv_sphere(0.3f, 8, 16));
    add_mesh("unused", bz::geo::pyramid(1.0f, 1.0f));
    for (int i = 0; i < 20; ++i) add_item(cube, at(-4.0 + 0.45 * i, 0.0, -1.0 * (i % 3)));
    for (int i = 0; i < 5; ++i) add_item(ball, at(-2.0 + i, 1.5, 0.0));

    const auto b = batches();
    ASSERT_EQ(b.batches.size(), 2u);  // one instanced draw per model
    EXPECT_EQ(b.batches[0].instance_count, 20);
    EXPECT_EQ(b.batches[1].instance_count, 5);
    EXPECT_EQ(b.stats.objects_drawn, 25u);

    const bz::test::Mask shared = mask("instancing_on");
    EXPECT_EQ(renderer->gpu_mesh_uploads(), 2u) << "the unused model must not be uploaded";
    mask();
    EXPECT_EQ(renderer->gpu_mesh_uploads(), 2u) << "meshes are uploaded once, not per frame";

    // One draw per object draws the same picture.
    settings.instancing = false;
    EXPECT_EQ(batches().batches.size(), 25u);
    EXPECT_EQ(mask("instancing_off").pixels, shared.pixels);
    EXPECT_EQ(renderer->gpu_mesh_uploads(), 2u);
}

TEST_F(SceneModellingTest, FrustumCullingSkipsOnlyWhatCannotShow) {
    const auto cube = add_mesh("cube", bz::geo::box(glm::vec3(0.5f)));
    const auto hidden_model = add_mesh("behind_only", bz::geo::uv_sphere(0.5f, 8, 16));
    for (int i = 0; i < 5; ++i) add_item(cube, at(-3.0 + 1.5 * i, 0.0, 0.0));  // in view
    for (int i = 0; i < 7; ++i) add_item(cube, at(-3.0 + i, 0.0, 30.0));       // behind the eye
    for (int i = 0; i < 3; ++i) add_item(cube, at(60.0 + 2.0 * i, 0.0, 0.0));  // far to the right
    add_item(hidden_model, at(0.0, 0.0, 40.0));                                // behind, own model
    add_item(cube, at(0.0, 0.0, -600.0));                                      // beyond far

    auto b = batches();
    EXPECT_EQ(b.stats.objects_drawn, 5u);
    EXPECT_EQ(b.stats.objects_culled, 12u);
    const bz::test::Mask culled = mask("culling_on");
    EXPECT_EQ(renderer->gpu_mesh_uploads(), 1u)
        << "a model whose every instance is culled stays on the CPU";

    settings.frustum_culling = false;
    b = batches();
    EXPECT_EQ(b.stats.objects_culled, 0u);
    EXPECT_EQ(b.stats.objects_drawn, 17u);
    EXPECT_EQ(mask("culling_off").pixels, culled.pixels);

    // An object straddling the frustum's side is kept.
    frame.items.clear();
    add_item(cube, at(7.2, 0.0, 0.0));
    settings.frustum_culling = true;
    EXPECT_EQ(batches().stats.objects_drawn, 1u);
}

TEST_F(SceneModellingTest, FarObjectsDrawSimplifiedMeshes) {
    const auto ball = add_mesh("ball", bz::geo::uv_sphere(1.0f, 32, 64));
    add_item(ball, at(0.0, 0.0, 6.0));       // near: full detail
    add_item(ball, at(-30.0, 0.0, -250.0));  // far: a few pixels across
    settings.lod = true;
    const auto b = batches();
    ASSERT_EQ(b.batches.size(), 2u);
    EXPECT_EQ(b.batches[0].lod, 0);
    EXPECT_EQ(b.batches[1].lod, 1);

    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    const std::size_t with_lod = renderer->stats().triangles_submitted;
    EXPECT_EQ(renderer->gpu_mesh_uploads(), 2u);  // the sphere and its simplified version
    const std::size_t full = meshes.mesh(ball).triangle_count();
    EXPECT_LT(with_lod, 2 * full - full / 3) << "the far sphere must submit fewer triangles";
    EXPECT_GT(with_lod, full);

    // The far sphere is tiny: its simplified outline still scores against the exact reference.
    const auto ref = bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
    const auto score = bz::geo::score_masks(mask("lod_on").pixels, ref, kWidth, kHeight, 1);
    EXPECT_GE(score.f1, 0.97);
    settings.lod = false;
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    EXPECT_EQ(renderer->stats().triangles_submitted, 2 * full);
}

}  // namespace
