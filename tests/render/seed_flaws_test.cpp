// The three flaws of the frame of the renderer this one grew from (Bernardoni 2018), each checked
// so they stay fixed: spurious diagonals across flat panels, dense line areas washed out to white,
// and stubs.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

using bz::test::expected_mask;
using bz::test::RenderTest;

namespace {

// A flat square panel in z = 0 (two triangles sharing the diagonal (0,0)-(1,1)), plus an exact
// duplicate of one triangle and a back-to-back twin of the other: the faces that made the
// original's "last write wins" adjacency draw a diagonal across a flat panel.
bz::geo::TriMesh dirty_panel() {
    bz::geo::TriMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3, /*duplicate*/ 0, 1, 2, /*twin*/ 4, 3, 5};
    return m;
}

}  // namespace

TEST_F(RenderTest, NoDiagonalAcrossAFlatPanelWithDuplicateAndTwinFaces) {
    add_item(add_mesh("panel", dirty_panel()));
    frame.camera.eye = {0.5, 0.5, 2.0};
    frame.camera.target = {0.5, 0.5, 0.0};
    frame.camera.fov_y_deg = 45.0;
    const auto got = mask("dirty_panel");
    const std::vector<std::pair<glm::dvec3, glm::dvec3>> border = {{{0, 0, 0}, {1, 0, 0}},
                                                                   {{1, 0, 0}, {1, 1, 0}},
                                                                   {{1, 1, 0}, {0, 1, 0}},
                                                                   {{0, 1, 0}, {0, 0, 0}}};
    const auto s =
        bz::test::score_masks(got, expected_mask(frame.camera, kWidth, kHeight, border), 1);
    EXPECT_EQ(s.precision, 1.0) << "lit pixels off the panel's border (a diagonal?)";
    EXPECT_GE(s.recall, 0.99);
}

TEST_F(RenderTest, DenseLinesStayGreenInsteadOfWashingOutToWhite) {
    // 400 spheres packed into a small patch of screen: lines everywhere, bloom on top.
    const auto sphere = add_mesh("sphere", bz::geo::uv_sphere(0.5f, 8, 16));
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            add_item(sphere, glm::translate(glm::dmat4(1.0),
                                            glm::dvec3(i * 1.05 - 10.0, j * 1.05 - 10.0, 0.0)));
        }
    }
    frame.camera.eye = {0.0, 0.0, 24.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    settings = bz::render::preset("high");
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    const auto rgba = renderer->read_color();
    save_color("dense_spheres");
    int bright = 0, whiteish = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        const int r = rgba[i], g = rgba[i + 1], b = rgba[i + 2];
        if (g > 150) ++bright;
        if (std::min({r, g, b}) > 200) ++whiteish;
    }
    EXPECT_GT(bright, kWidth * kHeight / 10) << "the scene should be densely lit";
    EXPECT_EQ(whiteish, 0) << "pixels washed out to white";
}

TEST_F(RenderTest, LinesMeetWithoutGapsOrStubs) {
    // The silhouette of a box seen face-on is a square of four lines meeting at corners. The
    // colour image must be lit at every corner (no gap) and dark one line-width beyond each
    // corner along both edges (no stub: caps are round, not extended rectangles).
    add_item(add_mesh("box", bz::geo::box(glm::vec3(1.0f, 1.0f, 0.1f))));
    frame.camera.eye = {0.0, 0.0, 6.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.camera.fov_y_deg = 40.0;
    settings = bz::render::preset("balanced");
    settings.bloom_strength = 0.0f;  // look at the lines themselves
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    const auto rgba = renderer->read_color();
    save_color("corners");
    const auto green = [&](int x, int y) {
        return rgba[static_cast<std::size_t>((y * kWidth + x) * 4 + 1)];
    };
    // Project the corner (1,1,0.1) exactly.
    const double f = 1.0 / std::tan(glm::radians(40.0) * 0.5);
    const double px = 1.0 * f / (double(kWidth) / kHeight) / 5.9, py = 1.0 * f / 5.9;
    const int cx = static_cast<int>((px * 0.5 + 0.5) * kWidth),
              cy = static_cast<int>((0.5 - py * 0.5) * kHeight);
    EXPECT_GT(green(cx, cy), 120) << "corner not lit";
    const int beyond = static_cast<int>(settings.line_half_width_px) + 3;
    EXPECT_LT(green(cx + beyond, cy - beyond), 10) << "stub beyond the corner";
    EXPECT_LT(green(cx + beyond, cy), 60) << "horizontal edge overshoots the corner";
    EXPECT_LT(green(cx, cy - beyond), 60) << "vertical edge overshoots the corner";
}
