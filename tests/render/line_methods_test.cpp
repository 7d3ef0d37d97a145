// The two feature-line methods (LineMethod::compute and LineMethod::geometry_shader) draw the
// same lines: on real models, against each other and against the exact CPU reference, and
// they count the same feature edges. (Every analytic mask test also compares them: see
// RenderTest::mask.)
#include <gtest/gtest.h>

#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/reference/mask_score.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

using bz::render::LineMethod;
using bz::test::Mask;
using bz::test::RenderTest;

class LineMethodsTest : public RenderTest {
  protected:
    Mask mask_with(LineMethod m, const std::string& name) {
        settings.method = m;
        compare_line_methods = false;
        return mask(name + "_" + bz::render::line_method_name(m));
    }
    // A finely divided sphere at a crease angle of 0, full detail, balanced: every edge is a
    // crease, about 100k of them face the eye - more records and spine samples than the edge
    // buffer first holds.
    void show_dense_creases() {
        add_item(add_mesh("sphere", bz::geo::uv_sphere(1.0f, 300, 600)));
        frame.camera.eye = {0.0, 1.0, 3.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        settings = bz::render::preset("balanced");
        settings.crease_angle_deg = 0.0f;
        settings.lod = false;
    }
};

TEST_F(LineMethodsTest, RealModelsSameMaskAndSameReferenceScore) {
    for (const char* path : bz::test::kRealModels) {
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path))
            << "install assimp-testmodels (tools/install-deps)";
        show_model(path);
        const std::string name = "methods_" + std::filesystem::path(path).stem().string();
        for (const char* preset : {"balanced", "high"}) {
            SCOPED_TRACE(preset);
            settings = bz::render::preset(preset);
            const Mask gs = mask_with(LineMethod::geometry_shader, name);
            const Mask cs = mask_with(LineMethod::compute, name);
            EXPECT_GT(gs.count(), 100);
            bz::test::expect_same_lines(cs, gs, name);
            const std::vector<std::uint8_t> ref =
                bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
            const auto f_gs = bz::geo::score_masks(gs.pixels, ref, kWidth, kHeight, 1).f1;
            const auto f_cs = bz::geo::score_masks(cs.pixels, ref, kWidth, kHeight, 1).f1;
            EXPECT_NEAR(f_cs, f_gs, 0.002) << "F1 compute " << f_cs << ", geometry shader " << f_gs;
            EXPECT_GT(f_cs, 0.9);
        }
    }
}

TEST_F(LineMethodsTest, BothCountTheSameFeatureEdges) {
    // Instanced spheres and open boxes: silhouettes, creases and boundary edges, several batches.
    const auto sphere = add_mesh("sphere", bz::geo::uv_sphere(1.0f, 10, 20));
    const auto open = add_mesh("open", bz::geo::open_box(glm::vec3(0.8f)));
    for (int i = 0; i < 4; ++i) {
        add_item(sphere, glm::translate(glm::dmat4(1.0), glm::dvec3(i * 2.5 - 4.0, 0.0, 0.0)));
        add_item(open, glm::translate(glm::dmat4(1.0), glm::dvec3(i * 2.5 - 4.0, 0.0, -3.0)));
    }
    frame.camera.eye = {1.0, 4.0, 9.0};
    frame.camera.target = {0.0, 0.0, -1.0};
    std::size_t counts[2] = {0, 0};
    int k = 0;
    for (const LineMethod m : {LineMethod::geometry_shader, LineMethod::compute}) {
        settings = bz::render::preset("balanced");
        settings.method = m;
        settings.count_edges = true;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        counts[k++] = renderer->stats().feature_edges;
    }
    EXPECT_GT(counts[0], 50u);
    EXPECT_EQ(counts[1], counts[0]);
}

TEST_F(LineMethodsTest, EdgeBufferGrowsPastItsFirstSize) {
    // More visible feature edges than the edge buffer's first size (65536 records, pass_edges):
    // at a crease angle of 0 every edge of a finely divided sphere is a crease, about 100k of
    // them face the eye. The mask must still be complete, and the same as the geometry shader's.
    show_dense_creases();
    settings.count_edges = true;
    const Mask gs = mask_with(LineMethod::geometry_shader, "grow");
    const Mask cs = mask_with(LineMethod::compute, "grow");
    bz::test::expect_same_lines(cs, gs, "grow");
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    EXPECT_GT(renderer->stats().feature_edges, 65536u);
}

TEST_F(LineMethodsTest, SpineSamplesScoreAsTheTestInEveryFragment) {
    // LineMethod::compute runs the spine test once per spine sample (1 px apart) and the
    // fragments look it up; spacing 0 runs it in every fragment instead. Same lines, and the
    // same score against the exact reference.
    for (const char* path : bz::test::kRealModels) {
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path))
            << "install assimp-testmodels (tools/install-deps)";
        show_model(path);
        const std::string name = "samples_" + std::filesystem::path(path).stem().string();
        settings = bz::render::preset("balanced");
        ASSERT_GT(settings.spine_sample_spacing_px, 0.0f);
        const Mask sampled = mask_with(LineMethod::compute, name);
        settings.spine_sample_spacing_px = 0.0f;
        const Mask per_fragment = mask_with(LineMethod::compute, name + "_per_fragment");
        EXPECT_GT(per_fragment.count(), 100);
        bz::test::expect_same_lines(sampled, per_fragment, name);
        const std::vector<std::uint8_t> ref =
            bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
        const auto f_sampled = bz::geo::score_masks(sampled.pixels, ref, kWidth, kHeight, 1).f1;
        const auto f_fragment =
            bz::geo::score_masks(per_fragment.pixels, ref, kWidth, kHeight, 1).f1;
        EXPECT_NEAR(f_sampled, f_fragment, 0.002)
            << "F1 samples " << f_sampled << ", every fragment " << f_fragment;
    }
}

TEST_F(LineMethodsTest, HiddenStretchesOfAnEdgeStayHiddenInTheColourImage) {
    // The quads cover only each edge's visible stretch of spine samples: a long crease that
    // passes behind a wall must light nothing where the wall hides it, and its visible ends
    // must reach the wall's edges.
    const auto floor = add_mesh("floor", bz::geo::open_box(glm::vec3(4.0f, 0.05f, 0.5f)));
    const auto wall = add_mesh("wall", bz::geo::open_box(glm::vec3(0.6f, 1.0f, 0.05f)));
    add_item(floor);
    add_item(wall, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, 1.5)));
    frame.camera.eye = {0.0, 0.3, 6.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    settings = bz::render::preset("balanced");
    settings.method = LineMethod::compute;
    compare_line_methods = false;
    const Mask m = mask("hidden_stretch");
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    const std::vector<std::uint8_t> rgba = renderer->read_color();
    const std::vector<std::uint8_t> ref =
        bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
    const auto score = bz::geo::score_masks(m.pixels, ref, kWidth, kHeight, 1);
    EXPECT_GT(score.precision, 0.99);
    EXPECT_GT(score.recall, 0.98);
    // The colour image lights no pixel (green above half) farther than the beam from a
    // reference line: no hidden stretch shows, and no quad runs past its visible stretch.
    int stray = 0, lit = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
            if (rgba[4 * i + 1] < 128) continue;
            ++lit;
            bool near = false;
            for (int dy = -3; dy <= 3 && !near; ++dy) {
                for (int dx = -3; dx <= 3 && !near; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= kWidth || yy >= kHeight) continue;
                    near = ref[static_cast<std::size_t>(yy) * kWidth + xx] != 0;
                }
            }
            stray += near ? 0 : 1;
        }
    }
    EXPECT_GT(lit, 200);
    EXPECT_EQ(stray, 0);
}

TEST_F(LineMethodsTest, FirstFrameIsTheSameAsLaterOnesWhenTheSamplesOutgrowTheirBuffer) {
    // About 100k visible creases ask for more spine samples than the buffer first holds. A
    // record left without samples is tested per fragment, which differs from the samples where
    // the test is a tie, and which records those are depends on the order of the atomic
    // appends: the first frame must size the buffers before it draws, so that a frame is the
    // same on every run and the same as the frames after it.
    show_dense_creases();
    settings.method = LineMethod::compute;
    auto draw = [&](bz::render::Renderer& r) {
        r.set_settings(settings);
        r.render(frame, meshes, bz::render::Renderer::kOffscreen);
        return r.read_color();
    };
    const std::vector<std::uint8_t> first = draw(*renderer);
    const std::vector<std::uint8_t> second = draw(*renderer);
    bz::render::Renderer fresh(settings, kWidth, kHeight, bz::gl::TimingMethod::off);
    const std::vector<std::uint8_t> other_run = draw(fresh);
    EXPECT_TRUE(first == second) << "the first frame differs from the second";
    EXPECT_TRUE(first == other_run) << "a fresh renderer's first frame differs";
}
