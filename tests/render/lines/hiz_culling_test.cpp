// Hierarchical-Z culling of edge clusters (render/lines/hiz_culling.h): the bounds records on
// analytic spheres, and on the GPU scenes where the answer is known: a wall that hides a
// sphere wholly, one that hides half of it, a sphere beside the wall, a cluster across the
// frustum's edge, a thin open sheet from both sides. The frame must be the one without the
// culling, byte for byte; where something is wholly hidden, clusters must be skipped.
#include "render/lines/hiz_culling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

render::HizView view_of(int width = 320, int height = 240) {
    return render::HizView(
        glm::perspective(glm::radians(50.0f), float(width) / float(height), 0.1f, 100.0f), 0.1f,
        width, height);
}

glm::ivec4 rect_of(const render::HizBounds& b) {
    return {int(b.x & 0xFFFFu), int(b.x >> 16), int(b.y & 0xFFFFu), int(b.y >> 16)};
}

TEST(HizBounds, ASmallSphereAheadCoversItsProjectionOnTheFineTiles) {
    const render::HizView v = view_of();
    const render::HizBounds b = render::hiz_bounds(v, glm::vec3(0.0f, 0.0f, -10.0f), 0.2f);
    ASSERT_EQ(b.w, 1u) << "fine level";
    // The centre projects to the middle of the screen: pixel (160, 120), fine tile (10, 7).
    const glm::ivec4 r = rect_of(b);
    EXPECT_LE(r.x, 10);
    EXPECT_GE(r.z, 10);
    EXPECT_LE(r.y, 7);
    EXPECT_GE(r.w, 7);
    // Its nearest point is 9.8 away.
    EXPECT_NEAR(glm::uintBitsToFloat(b.z), 1.0 / 9.8, 1e-6);
}

TEST(HizBounds, ALargeSphereTakesTheCoarseTilesAndAHugeOneNoTest) {
    const render::HizView v = view_of(1920, 1080);
    const render::HizBounds mid = render::hiz_bounds(v, glm::vec3(0.0, 0.0, -10.0), 1.5f);
    EXPECT_EQ(mid.w, 2u) << "more than 64 fine tiles: the coarse level";
    const render::HizBounds huge = render::hiz_bounds(v, glm::vec3(0.0, 0.0, -10.0), 8.0f);
    EXPECT_EQ(huge.w, 0u) << "more than 64 coarse tiles: untested";
}

TEST(HizBounds, NoTestAcrossTheNearPlaneBehindTheEyeOrOffScreen) {
    const render::HizView v = view_of();
    EXPECT_EQ(render::hiz_bounds(v, glm::vec3(0.0, 0.0, -0.15), 0.1f).w, 0u);
    EXPECT_EQ(render::hiz_bounds(v, glm::vec3(0.0, 0.0, 5.0), 1.0f).w, 0u);
    EXPECT_EQ(render::hiz_bounds(v, glm::vec3(100.0, 0.0, -10.0), 0.5f).w, 0u);
}

TEST(HizBounds, ASphereAcrossTheScreenEdgeIsClampedToIt) {
    const render::HizView v = view_of();
    // Half off the right edge: x = tan(25 deg) * 4/3 * 10 is the edge at depth 10.
    const double edge = std::tan(glm::radians(25.0)) * (4.0 / 3.0) * 10.0;
    const render::HizBounds b = render::hiz_bounds(v, glm::vec3(edge, 0.0, -10.0), 0.2f);
    ASSERT_EQ(b.w, 1u);
    EXPECT_EQ(rect_of(b).z, (320 - 1) / render::kDepthTileSize);
}

class HizCullingTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        use_repeatable_compute_frames();
        frame.items.clear();
        sphere_ = add_mesh("sphere", geo::uv_sphere(1.0f, 48, 96));
        wall_ = add_mesh("wall", geo::grid(3, 3, 1.0f, 3));
        frame.camera.eye = glm::vec3(0.0, 0.0, 6.0);
        frame.camera.target = glm::vec3(0.0);
    }
    // A 3 x 3 wall (the grid stood up to face +z) at z = 2 centred at x, and the unit sphere
    // at the origin (or at x = sphere_x); the eye at z = 6.
    void place(double wall_x, double sphere_x = 0.0) {
        frame.items.clear();
        add_item(sphere_, glm::translate(glm::dmat4(1.0), glm::dvec3(sphere_x, 0.0, 0.0)));
        if (std::isnan(wall_x)) return;
        add_item(wall_, glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(wall_x, 0.0, 2.0)),
                                    glm::radians(90.0), glm::dvec3(1.0, 0.0, 0.0)));
    }
    // The picture and the mask with hierarchical-Z culling off and on; returns the clusters it
    // skipped.
    std::size_t expect_same_frames(const std::string& what) {
        std::vector<std::uint8_t> pictures[2];
        std::size_t hidden = 0;
        for (const bool hiz : {false, true}) {
            settings.hiz_culling = hiz;
            renderer->set_settings(settings);
            renderer->render(frame, meshes, render::Renderer::kOffscreen);
            pictures[hiz] = renderer->read_color();
            if (hiz)
                hidden = renderer->hiz_hidden_clusters();
            else
                EXPECT_EQ(renderer->hiz_hidden_clusters(), 0u) << what;
        }
        EXPECT_EQ(pictures[0], pictures[1]) << what << ": the picture changed";
        std::size_t lit = 0;
        for (std::size_t i = 0; i < pictures[1].size(); i += 4) lit += pictures[1][i + 1] > 40;
        EXPECT_GT(lit, 100u) << what << ": nothing drawn, the comparison means nothing";
        return hidden;
    }
    scene::MeshId sphere_{}, wall_{};
};

TEST_F(HizCullingTest, AWallThatHidesTheSphereSkipsItsClusters) {
    // The sphere alone: the clusters the CPU gives the edges pass, none hidden (a convex
    // surface hides none of its own front).
    place(std::nan(""));
    EXPECT_EQ(expect_same_frames("the sphere alone"), 0u);
    const std::size_t sphere_items = renderer->stats().edge_culling.items;
    ASSERT_GT(sphere_items, 20u);
    // The wall covers the sphere's outline with room to spare (20.6 against 9.6 degrees): the
    // sphere's clusters are skipped, and none of the wall's own. A cluster whose rectangle
    // spans more than 64 fine tiles is tested on the coarse ones (128 px at 320x240), which
    // reach past the wall: such a one stays, so not quite all of them go.
    place(0.0);
    const std::size_t hidden = expect_same_frames("wall over the sphere");
    EXPECT_LE(hidden, sphere_items);
    EXPECT_GE(hidden * 10, sphere_items * 9) << hidden << " of " << sphere_items;
}

TEST_F(HizCullingTest, HalfHiddenHalfSeenAndBeside) {
    place(1.0);  // the wall covers the sphere's right half
    const std::size_t half = expect_same_frames("half behind the wall");
    EXPECT_GT(half, 0u);
    place(4.0);  // the wall beside the sphere: nothing of it hidden
    EXPECT_EQ(expect_same_frames("wall beside"), 0u);
}

TEST_F(HizCullingTest, AClusterAcrossTheFrustumsEdge) {
    // The sphere half out of the view, behind a wall that covers the part in view.
    place(2.5, 2.9);
    expect_same_frames("sphere across the right edge");
}

TEST_F(HizCullingTest, AThinOpenSheetFromBothSides) {
    // A sheet just in front of the sphere (0.01 past its surface) from the front, then seen
    // from behind the sphere: the sheet hides it, then it hides the sheet's middle.
    frame.items.clear();
    add_item(sphere_);
    add_item(wall_, glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, 1.01)),
                                glm::radians(90.0), glm::dvec3(1.0, 0.0, 0.0)));
    expect_same_frames("sheet in front");
    frame.camera.eye = glm::dvec3(0.0, 0.0, -6.0);
    expect_same_frames("sheet behind");
}

TEST_F(HizCullingTest, RealModelsDrawTheSameFrame) {
    for (const char* path :
         {"/usr/share/assimp/models/BLEND/Suzanne_248.blend",
          "/usr/share/assimp/models/OBJ/spider.obj", "/usr/share/assimp/models/3DS/fels.3ds"}) {
        show_model(path);
        expect_same_frames(path);
    }
}

}  // namespace
}  // namespace bz::test
