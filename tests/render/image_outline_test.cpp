// The image-space outline baseline (LineMethod::image_outline): Sobel on the prepass depth and
// normals finds a cube's outline and creases, in the same mask format as the line pass.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/generated/primitives.h"
#include "geometry/reference/mask_score.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

namespace {

class ImageOutlineTest : public bz::test::RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        add_item(add_mesh("cube", bz::geo::box(glm::vec3(0.5f))));
        frame.camera.eye = {1.9, 1.4, 2.6};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 40.0;
        frame.camera.near = 0.1;
        frame.camera.far = 100.0;
        settings = bz::render::preset("balanced");
        settings.method = bz::render::LineMethod::image_outline;
    }
};

TEST_F(ImageOutlineTest, FindsTheCubesVisibleEdges) {
    const bz::test::Mask m = mask("outline_cube");
    const auto ref = bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
    const auto s = bz::geo::score_masks(m.pixels, ref, kWidth, kHeight, 1);
    // Its lines are up to two pixels wide (both sides of a crease): precise within 1 px.
    EXPECT_GE(s.precision, 0.95);
    EXPECT_GE(s.recall, 0.9);
    EXPECT_GT(m.count(), 300);
}

TEST_F(ImageOutlineTest, DrawsIntoTheSameFrameAsTheLinePass) {
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    int lit = 0;
    bool finite = true;
    for (float v : renderer->read_lines_hdr()) {
        finite = finite && std::isfinite(v);
        lit += v > 0.0f ? 1 : 0;
    }
    EXPECT_TRUE(finite);
    EXPECT_GT(lit, 300);
    // Switching back to the geometry method works on the same renderer.
    settings.method = bz::render::LineMethod::geometry_shader;
    EXPECT_GT(mask().count(), 300);
}

}  // namespace
