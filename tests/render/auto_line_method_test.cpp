// LineMethod::automatic ("auto"): each frame is drawn by the geometry shader below
// kAutoComputeFromTriangles submitted triangles and by the compute method from there, and a
// sequence of frames that crosses the threshold draws every frame as the method it picked
// would have drawn it on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "core/error.h"
#include "geometry/generated/primitives.h"
#include "gl/driver.h"
#include "render/render_fixture.h"

using bz::render::LineMethod;
using bz::render::Renderer;
using bz::test::RenderTest;

TEST(AutoLineMethod, ResolvesByTheTrianglesAFrameSubmitsOnASoftwareRasteriser) {
    using bz::render::kAutoComputeFromTriangles;
    using bz::render::resolve_line_method;
    constexpr bool kSoftware = true;
    EXPECT_EQ(resolve_line_method(LineMethod::automatic, 0, kSoftware),
              LineMethod::geometry_shader);
    EXPECT_EQ(resolve_line_method(LineMethod::automatic, kAutoComputeFromTriangles - 1, kSoftware),
              LineMethod::geometry_shader);
    EXPECT_EQ(resolve_line_method(LineMethod::automatic, kAutoComputeFromTriangles, kSoftware),
              LineMethod::compute);
    EXPECT_EQ(resolve_line_method(LineMethod::automatic, 10 * kAutoComputeFromTriangles, kSoftware),
              LineMethod::compute);
    // A method given outright stays, whatever the frame and the machine.
    for (const LineMethod m :
         {LineMethod::compute, LineMethod::geometry_shader, LineMethod::image_outline}) {
        for (const bool software : {true, false}) {
            EXPECT_EQ(resolve_line_method(m, 0, software), m);
            EXPECT_EQ(resolve_line_method(m, 10 * kAutoComputeFromTriangles, software), m);
        }
    }
}

TEST(AutoLineMethod, DrawsWithComputeAtEverySizeOnAHardwareGpu) {
    using bz::render::kAutoComputeFromTriangles;
    using bz::render::resolve_line_method;
    constexpr bool kHardware = false;
    for (const std::size_t triangles :
         {std::size_t{0}, std::size_t{12}, kAutoComputeFromTriangles - 1, kAutoComputeFromTriangles,
          10 * kAutoComputeFromTriangles}) {
        EXPECT_EQ(resolve_line_method(LineMethod::automatic, triangles, kHardware),
                  LineMethod::compute)
            << triangles << " triangles";
    }
}

TEST(AutoLineMethod, ParsesAutoAndNamesIt) {
    EXPECT_EQ(bz::render::parse_line_method("auto"), LineMethod::automatic);
    EXPECT_STREQ(bz::render::line_method_name(LineMethod::automatic), "auto");
    try {
        bz::render::parse_line_method("automatic");
        ADD_FAILURE() << "no error for 'automatic'";
    } catch (const bz::UserError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown line method 'automatic'"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("auto"), std::string::npos) << e.what();
    }
    // auto is no third set of lines: the feature-line methods stay the two it picks from.
    const auto& methods = bz::render::feature_line_methods();
    EXPECT_EQ(std::count(methods.begin(), methods.end(), LineMethod::automatic), 0);
}

namespace {

class AutoLineMethodTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        settings = bz::render::preset("balanced");
        settings.lod = false;  // the submitted triangles are the meshes' own
        sphere_ = add_mesh("sphere", bz::geo::uv_sphere(0.4f, 12, 24));
        sphere_triangles_ = bz::geo::uv_sphere(0.4f, 12, 24).triangle_count();
    }

    // One sphere in front of the camera: far below the threshold.
    bz::scene::FrameList small_frame(double turn) const {
        bz::scene::FrameList f = frame;
        f.items.clear();
        bz::scene::DrawItem item;
        item.mesh = sphere_;
        item.model = glm::rotate(glm::dmat4(1.0), turn, glm::dvec3(0.0, 1.0, 0.0));
        f.items.push_back(item);
        f.camera.eye = {0.0, 0.6, 2.0};
        f.camera.target = {0.0, 0.0, 0.0};
        return f;
    }

    // Enough spheres on a grid, all in view, for twice the threshold's triangles.
    bz::scene::FrameList large_frame(double turn) const {
        bz::scene::FrameList f = frame;
        f.items.clear();
        const std::size_t want = 2 * bz::render::kAutoComputeFromTriangles / sphere_triangles_ + 1;
        const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(want))));
        for (int i = 0; i < side * side; ++i) {
            bz::scene::DrawItem item;
            item.mesh = sphere_;
            const glm::dvec3 at((i % side - (side - 1) * 0.5) * 1.0, 0.0,
                                (i / side - (side - 1) * 0.5) * 1.0);
            item.model = glm::rotate(glm::translate(glm::dmat4(1.0), at), turn + i,
                                     glm::dvec3(0.0, 1.0, 0.0));
            f.items.push_back(item);
        }
        f.camera.eye = {0.0, 1.2 * side, 1.6 * side};
        f.camera.target = {0.0, 0.0, 0.0};
        return f;
    }

    // Draws `f` and returns the colour image.
    static std::vector<std::uint8_t> draw(Renderer& r, const bz::scene::FrameList& f,
                                          const bz::scene::MeshLibrary& meshes) {
        r.render(f, meshes, Renderer::kOffscreen);
        return r.read_color();
    }

    static std::vector<std::string> pass_names(const Renderer& r) {
        std::vector<std::string> names;
        for (const auto& p : r.pass_times()) names.emplace_back(p.name);
        return names;
    }

    static bool has(const std::vector<std::string>& names, const std::string& name) {
        return std::find(names.begin(), names.end(), name) != names.end();
    }

    bz::scene::MeshId sphere_{};
    std::size_t sphere_triangles_ = 0;
};

}  // namespace

TEST_F(AutoLineMethodTest, PicksTheGeometryShaderBelowTheThresholdAndComputeFromIt) {
    settings.method = LineMethod::automatic;
    Renderer r(settings, kWidth, kHeight, bz::gl::TimingMethod::cpu_finish);

    // On a hardware GPU auto draws every frame with compute (resolve_line_method).
    const LineMethod small_method =
        bz::gl::is_software_renderer() ? LineMethod::geometry_shader : LineMethod::compute;
    r.render(small_frame(0.0), meshes, Renderer::kOffscreen);
    EXPECT_LT(r.stats().triangles_submitted, bz::render::kAutoComputeFromTriangles);
    EXPECT_EQ(r.line_method_drawn(), small_method);
    EXPECT_EQ(r.settings().method, LineMethod::automatic);  // the setting stays auto
    std::vector<std::string> names = pass_names(r);
    EXPECT_TRUE(has(names, "lines"));
    EXPECT_EQ(has(names, "edges"), small_method == LineMethod::compute);
    EXPECT_EQ(has(names, "visibility"), small_method == LineMethod::compute);

    r.render(large_frame(0.0), meshes, Renderer::kOffscreen);
    EXPECT_GE(r.stats().triangles_submitted, bz::render::kAutoComputeFromTriangles);
    EXPECT_EQ(r.line_method_drawn(), LineMethod::compute);
    names = pass_names(r);
    EXPECT_TRUE(has(names, "edges"));
    EXPECT_TRUE(has(names, "visibility"));
    EXPECT_TRUE(has(names, "lines"));

    // The mask picks the same way.
    r.render_mask(small_frame(0.0), meshes);
    EXPECT_EQ(r.line_method_drawn(), small_method);
    r.render_mask(large_frame(0.0), meshes);
    EXPECT_EQ(r.line_method_drawn(), LineMethod::compute);
}

TEST_F(AutoLineMethodTest, FramesCrossingTheThresholdLookAsTheMethodItPickedDrawsThem) {
    // Small and large frames in turn: auto switches method every frame. Each frame must be the
    // picture of the method it picked, drawn by a renderer that used that method all along.
    if (!bz::gl::is_software_renderer()) {
        GTEST_SKIP()
            << "auto switches methods only on a software rasteriser; on a hardware GPU "
               "it draws every frame with compute (DrawsWithComputeAtEverySizeOnAHardwareGpu)";
    }
    const std::vector<bz::scene::FrameList> frames = {
        small_frame(0.0), large_frame(0.0), small_frame(0.3), large_frame(0.5),
        large_frame(0.9), small_frame(0.6), small_frame(0.7), large_frame(1.3)};
    bz::render::RenderSettings s = settings;
    s.method = LineMethod::automatic;
    Renderer automatic(s, kWidth, kHeight, bz::gl::TimingMethod::off);
    s.method = LineMethod::compute;
    Renderer compute(s, kWidth, kHeight, bz::gl::TimingMethod::off);
    s.method = LineMethod::geometry_shader;
    Renderer geometry(s, kWidth, kHeight, bz::gl::TimingMethod::off);

    int picked_compute = 0;
    int picked_geometry = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        SCOPED_TRACE("frame " + std::to_string(i));
        const std::vector<std::uint8_t> a = draw(automatic, frames[i], meshes);
        const std::vector<std::uint8_t> c = draw(compute, frames[i], meshes);
        const std::vector<std::uint8_t> g = draw(geometry, frames[i], meshes);
        const bool large = i == 1 || i == 3 || i == 4 || i == 7;
        ASSERT_EQ(automatic.line_method_drawn(),
                  large ? LineMethod::compute : LineMethod::geometry_shader);
        const std::vector<std::uint8_t>& expected = large ? c : g;
        (large ? picked_compute : picked_geometry) += 1;
        EXPECT_TRUE(a == expected)
            << "auto's frame differs from " << (large ? "compute" : "geometry_shader") << "'s";
        const auto lit = std::count_if(a.begin(), a.end(), [](std::uint8_t v) { return v > 64; });
        EXPECT_GT(lit, 100) << "the frame shows no lines";
    }
    EXPECT_EQ(picked_compute, 4);
    EXPECT_EQ(picked_geometry, 4);
}

TEST_F(AutoLineMethodTest,
       AComputeFrameAfterGeometryShaderFramesSizesTheEdgeBufferFromItsOwnCounts) {
    // The edge buffer sizes a frame's records and spine samples from the frame before. After
    // frames the geometry shader drew, the counts it kept belong to an older, smaller frame:
    // a large frame sized from them would outgrow its spine samples and test the records left
    // without samples per fragment, which differs from the samples where the spine test is a
    // tie. It must be drawn as a compute renderer's first frame of it is: sized from its own
    // counts.
    if (!bz::gl::is_software_renderer()) {
        GTEST_SKIP()
            << "auto switches methods only on a software rasteriser; on a hardware GPU "
               "it draws every frame with compute (DrawsWithComputeAtEverySizeOnAHardwareGpu)";
    }
    bz::scene::FrameList dense = frame;
    dense.items.clear();
    bz::scene::DrawItem item;
    item.mesh = add_mesh("dense sphere", bz::geo::uv_sphere(1.0f, 300, 600));
    dense.items.push_back(item);
    dense.camera.eye = {0.0, 1.0, 3.0};
    dense.camera.target = {0.0, 0.0, 0.0};
    settings.crease_angle_deg = 0.0f;  // every edge a crease: about 100k face the eye

    bz::render::RenderSettings s = settings;
    s.method = LineMethod::automatic;
    Renderer automatic(s, kWidth, kHeight, bz::gl::TimingMethod::off);
    draw(automatic, large_frame(0.0), meshes);
    ASSERT_EQ(automatic.line_method_drawn(), LineMethod::compute);
    draw(automatic, small_frame(0.0), meshes);
    ASSERT_EQ(automatic.line_method_drawn(), LineMethod::geometry_shader);
    const std::vector<std::uint8_t> a = draw(automatic, dense, meshes);
    ASSERT_EQ(automatic.line_method_drawn(), LineMethod::compute);

    s.method = LineMethod::compute;
    Renderer fresh(s, kWidth, kHeight, bz::gl::TimingMethod::off);
    const std::vector<std::uint8_t> first = draw(fresh, dense, meshes);
    EXPECT_TRUE(a == first)
        << "the dense frame after a geometry-shader frame differs from a compute "
           "renderer's first frame of it";
}
