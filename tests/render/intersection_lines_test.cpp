// Intersection lines (RenderSettings::intersection_lines): both feature-line methods draw
// where surfaces cross as the exact CPU reference does, on scenes whose objects pass through
// each other (a box sunk into a ground, a cylinder through a box, a sphere through a plane,
// real models overlapping), in every style; the crossings are computed once while nothing
// moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/import/import.h"
#include "geometry/reference/mask_score.h"
#include "render/camera/camera_framing.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

using bz::render::LineMethod;
using bz::test::Mask;
using bz::test::RenderTest;

namespace {

glm::dmat4 xsect_at(glm::dvec3 p, double scale = 1.0) {
    return glm::scale(glm::translate(glm::dmat4(1.0), p), glm::dvec3(scale));
}

std::ptrdiff_t xsect_lit(const std::vector<std::uint8_t>& m) {
    return std::count_if(m.begin(), m.end(), [](std::uint8_t v) { return v != 0; });
}

}  // namespace

class IntersectionLinesTest : public RenderTest {
  protected:
    Mask mask_with(LineMethod m, bool on, const std::string& name) {
        settings.method = m;
        settings.intersection_lines = on;
        compare_line_methods = false;
        return mask(name + (on ? "_xsect_" : "_plain_") + bz::render::line_method_name(m));
    }
    std::vector<std::uint8_t> reference(bool on) {
        bz::render::ReferenceFrameOptions o;
        o.crease_angle_deg = settings.crease_angle_deg;
        o.intersection_lines = on;
        return bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight, o);
    }
    // Both methods, on and off, against the reference; on must add pixels.
    void expect_agreement(const std::string& name) {
        const std::vector<std::uint8_t> ref_on = reference(true), ref_off = reference(false);
        EXPECT_GT(xsect_lit(ref_on), xsect_lit(ref_off)) << "no crossing in view";
        for (const LineMethod m : bz::render::feature_line_methods()) {
            SCOPED_TRACE(bz::render::line_method_name(m));
            const Mask on = mask_with(m, true, name);
            const Mask off = mask_with(m, false, name);
            const double f1_on = bz::geo::score_masks(on.pixels, ref_on, kWidth, kHeight, 1).f1;
            const double f1_off = bz::geo::score_masks(off.pixels, ref_off, kWidth, kHeight, 1).f1;
            std::printf("%s %s: F1 intersection lines on %.4f, off %.4f (lit %d / %d)\n",
                        name.c_str(), bz::render::line_method_name(m), f1_on, f1_off, on.count(),
                        off.count());
            EXPECT_GE(f1_on, 0.99);
            EXPECT_GE(f1_off, 0.99);
            EXPECT_GT(on.count(), off.count());
        }
    }
    void sunk_box() {
        const auto ground = add_mesh("xsect_ground", bz::geo::grid(8, 8, 1.0f, 4));
        const auto cube = add_mesh("xsect_cube", bz::geo::box(glm::vec3(1.0f)));
        add_item(ground);
        add_item(cube, xsect_at({0.3, 0.4, -0.2}));
        frame.camera.eye = {3.5, 3.0, 6.0};
        frame.camera.target = {0.0, 0.3, 0.0};
        settings = bz::render::preset("high");
        settings.lod = false;
    }
};

TEST_F(IntersectionLinesTest, BoxSunkIntoGroundDrawsItsVisibleFootprint) {
    sunk_box();
    // The footprint's sides in front (z = 0.8) and on the right (x = 1.3) are in view; the
    // other two are behind the box.
    const std::vector<std::pair<glm::dvec3, glm::dvec3>> visible = {
        {{-0.7, 0.0, 0.8}, {1.3, 0.0, 0.8}}, {{1.3, 0.0, 0.8}, {1.3, 0.0, -1.2}}};
    const Mask want = bz::test::expected_mask(frame.camera, kWidth, kHeight, visible);
    for (const LineMethod m : bz::render::feature_line_methods()) {
        SCOPED_TRACE(bz::render::line_method_name(m));
        const Mask on = mask_with(m, true, "xsect_sunk_box");
        const Mask off = mask_with(m, false, "xsect_sunk_box");
        EXPECT_GE(bz::test::score_masks(on, want, 1).recall, 0.99) << "footprint drawn";
        EXPECT_LT(bz::test::score_masks(off, want, 1).recall, 0.5) << "without: not drawn";
    }
    expect_agreement("xsect_sunk_box");
    settings.intersection_lines = true;
    settings.method = LineMethod::compute;
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    save_color("xsect_sunk_box_vector");
}

TEST_F(IntersectionLinesTest, CylinderThroughBoxAndSphereThroughPlane) {
    const auto cube = add_mesh("xsect_box", bz::geo::box(glm::vec3(1.0f, 0.6f, 0.8f)));
    const auto cyl = add_mesh("xsect_cylinder", bz::geo::cylinder(0.4f, 1.6f, 24));
    const auto sphere = add_mesh("xsect_sphere", bz::geo::uv_sphere(0.7f, 16, 32));
    const auto plane = add_mesh("xsect_plane", bz::geo::grid(4, 4, 1.0f, 2));
    add_item(cube);
    // Tilted, through the box's top and out of its front.
    add_item(cyl, glm::rotate(xsect_at({0.2, 0.3, 0.3}), 0.6, glm::dvec3(1.0, 0.0, 0.3)));
    add_item(plane, xsect_at({2.5, -0.2, 0.0}, 0.6));
    add_item(sphere, xsect_at({2.5, 0.0, 0.0}));
    frame.camera.eye = {1.5, 3.0, 6.5};
    frame.camera.target = {1.2, 0.0, 0.0};
    settings = bz::render::preset("high");
    settings.lod = false;
    expect_agreement("xsect_shapes");
}

TEST_F(IntersectionLinesTest, RealModelsOverlappingAgreeWithTheReference) {
    // Two copies of a real model, the second half a body length along and turned, so that
    // their surfaces pass through each other; and a model with a ground plane through it.
    for (const char* path :
         {"/usr/share/assimp/models/PLY/Wuson.ply", "/usr/share/assimp/models/Collada/duck.dae"}) {
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path))
            << "install assimp-testmodels (tools/install-deps)";
        const bz::scene::MeshId id = show_model(path);
        const bz::geo::Bounds b = meshes.bounds(id);
        const glm::dvec3 size = glm::dvec3(b.max - b.min);
        add_item(id, glm::rotate(xsect_at({size.x * 0.45, size.y * 0.1, size.z * 0.2}), 0.7,
                                 glm::dvec3(0.0, 1.0, 0.0)));
        const auto ground = add_mesh(std::string(path) + "_ground", bz::geo::grid(2, 2, 1.0f, 1));
        const glm::dvec3 c = glm::dvec3(b.center());
        add_item(ground, xsect_at({c.x, c.y - size.y * 0.2, c.z}, glm::length(size)));
        bz::geo::Bounds all = b;
        all.max += glm::vec3(size * 0.6);
        frame.camera = bz::render::frame_bounds(all, 50.0, double(kWidth) / kHeight);
        settings = bz::render::preset("high");
        expect_agreement("xsect_" + std::filesystem::path(path).stem().string());
    }
}

TEST_F(IntersectionLinesTest, ComputedOnceWhileNothingMovesAndAgainForWhatMoves) {
    sunk_box();
    const auto cube = frame.items[1].mesh;
    add_item(cube, xsect_at({-2.0, 0.2, 1.5}, 0.5));  // a second box, sunk elsewhere
    settings.intersection_lines = true;
    renderer->set_settings(settings);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    const bz::render::IntersectionStats first = renderer->stats().intersections;
    EXPECT_EQ(first.pairs, 2u);
    EXPECT_EQ(first.pairs_computed, 2u);
    EXPECT_EQ(first.meshes_computed, 2u);
    EXPECT_GT(first.segments, 0u);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    EXPECT_EQ(renderer->stats().intersections.pairs_computed, 0u);
    EXPECT_EQ(renderer->stats().intersections.meshes_computed, 0u);
    EXPECT_EQ(renderer->stats().intersections.segments, first.segments);
    // The second box moves: its pair only.
    frame.items[2].model = xsect_at({-2.0, 0.1, 1.4}, 0.5);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    EXPECT_EQ(renderer->stats().intersections.pairs, 2u);
    EXPECT_EQ(renderer->stats().intersections.pairs_computed, 1u);
    EXPECT_EQ(renderer->stats().intersections.meshes_computed, 0u);
    EXPECT_GT(renderer->stats().intersections.segments, 0u);
    // Lifted out of the ground: no pair; the first box's segments are the ones it had.
    const std::size_t second_box = renderer->stats().intersections.segments;
    frame.items[2].model = xsect_at({-2.0, 0.6, 1.4}, 0.5);
    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    EXPECT_EQ(renderer->stats().intersections.pairs, 1u);
    EXPECT_EQ(renderer->stats().intersections.pairs_computed, 0u);
    EXPECT_LT(renderer->stats().intersections.segments, second_box);
}

TEST_F(IntersectionLinesTest, EveryStyleDrawsThemWithoutGlErrors) {
    sunk_box();
    settings.intersection_lines = true;
    for (const LineMethod m : bz::render::feature_line_methods()) {
        settings.method = m;
        for (const bz::scene::Style s : bz::scene::all_styles()) {
            settings.style = s;
            renderer->set_settings(settings);
            renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
            if (m == LineMethod::compute)
                save_color(std::string("xsect_sunk_box_") + std::string(bz::scene::style_name(s)));
        }
    }
    settings.style.reset();
}
