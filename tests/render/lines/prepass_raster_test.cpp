// The compute prepass (render/lines/prepass_raster.h): small clusters rasterised by a compute
// shader must leave the depth the GL pipeline leaves, pixel centre for pixel centre, up to
// float rounding, and the same lines; big clusters, clusters across the near plane and small
// scenes stay on the pipeline. Scenes where the answer is known: a dense sphere from outside
// (closed: back faces skipped), a dense open sheet from both sides, a mirrored instance, a
// close-up, the eye inside a sphere; then real models.
#include "render/lines/prepass_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "gl/driver.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

struct PrepassDepth {
    std::vector<float> depth;
    std::size_t computed = 0;  // triangles the compute shader rasterised
    std::size_t drawn = 0;     // triangles of the kept clusters
};

// How two prepass depths of one frame differ.
struct DepthDiff {
    std::size_t covered = 0;   // pixels the pipeline covered
    std::size_t coverage = 0;  // pixels covered by one only
    // Pixels covered by both whose depths differ by more than float rounding (1e-5 of the
    // depth) plus 1/16 of the depth's step to a neighbouring pixel: the pipeline snaps
    // vertices to 1/256 px, which moves a plane's depth at a pixel centre by a fraction of
    // that step; the spine test allows 1/16 px of it (RenderSettings::plane_tolerance_px).
    std::size_t depth = 0;
};

DepthDiff compare_depths(const std::vector<float>& pipeline, const std::vector<float>& compute,
                         int width, int height) {
    DepthDiff d;
    const auto at = [&](int x, int y) {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        return double(pipeline[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
    };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            const bool a = pipeline[i] > 0.0f, b = compute[i] > 0.0f;  // reversed-Z: 0 clear
            d.covered += a;
            if (a != b) {
                ++d.coverage;
                continue;
            }
            if (!a) continue;
            const double p = pipeline[i];
            const double step = std::max({std::abs(at(x + 1, y) - p), std::abs(at(x - 1, y) - p),
                                          std::abs(at(x, y + 1) - p), std::abs(at(x, y - 1) - p)});
            d.depth += std::abs(p - double(compute[i])) > 1e-5 * p + step / 16.0;
        }
    }
    return d;
}

class PrepassRasterTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        settings.beam = render::beam_look("classic");  // no flicker: frames repeat exactly
        frame.style = scene::Style::vector;
        frame.items.clear();
    }
    PrepassDepth depth_with(render::PrepassRaster raster) {
        settings.prepass_raster = raster;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, render::Renderer::kOffscreen);
        const render::TriangleCullStats& s = renderer->stats().triangle_culling;
        return {renderer->read_depth(), s.triangles_computed, s.triangles_drawn};
    }
    // The frame's depth by the pipeline and by compute; returns compute's.
    PrepassDepth expect_same_depth(const std::string& what, double max_coverage_share = 0.002) {
        const PrepassDepth pipeline = depth_with(render::PrepassRaster::pipeline);
        EXPECT_EQ(pipeline.computed, 0u) << what;
        const PrepassDepth compute = depth_with(render::PrepassRaster::compute);
        const DepthDiff d = compare_depths(pipeline.depth, compute.depth, kWidth, kHeight);
        EXPECT_GT(d.covered, 1000u) << what << ": nothing drawn, the comparison means nothing";
        // Coverage may differ only where a pixel centre lies within the pipeline's vertex
        // snapping (1/256 px) of a silhouette: a few pixels along the outline.
        EXPECT_LE(double(d.coverage), max_coverage_share * double(d.covered))
            << what << ": " << d.coverage << " of " << d.covered << " pixels covered by one only";
        // Depth: where a neighbour is another surface the step says little, so a few.
        EXPECT_LE(double(d.depth), max_coverage_share * double(d.covered))
            << what << ": " << d.depth << " of " << d.covered << " pixels differ in depth";
        std::printf("%s: %zu pixels covered, %zu by one only, %zu differ in depth\n", what.c_str(),
                    d.covered, d.coverage, d.depth);
        return compute;
    }
};

TEST_F(PrepassRasterTest, ADenseSphereFromOutsideGivesThePipelinesDepth) {
    add_item(add_mesh("sphere", geo::uv_sphere(1.0f, 96, 192)));
    frame.camera.eye = glm::dvec3(0.0, 0.5, 3.5);
    frame.camera.target = glm::dvec3(0.0);
    const PrepassDepth c = expect_same_depth("dense sphere");
    EXPECT_GT(c.computed * 10, c.drawn * 9) << c.computed << " of " << c.drawn;
}

TEST_F(PrepassRasterTest, ADenseOpenSheetFromBothSidesAndMirrored) {
    const scene::MeshId sheet = add_mesh("sheet", geo::grid(96, 96, 4.0f / 96.0f, 8));
    const glm::dmat4 standing =
        glm::rotate(glm::dmat4(1.0), glm::radians(70.0), glm::dvec3(1.0, 0.2, 0.0));
    add_item(sheet, standing);
    frame.camera.target = glm::dvec3(0.0);
    for (const double z : {5.0, -5.0}) {
        frame.camera.eye = glm::dvec3(0.3, 0.8, z);
        const PrepassDepth c = expect_same_depth(z > 0 ? "sheet, front" : "sheet, back");
        EXPECT_GT(c.computed, 0u);
    }
    frame.items.clear();
    add_item(sheet, glm::scale(standing, glm::dvec3(-1.0, 1.0, 1.0)));  // mirrored
    frame.camera.eye = glm::dvec3(0.3, 0.8, 5.0);
    expect_same_depth("sheet, mirrored");
}

TEST_F(PrepassRasterTest, BigClustersAndTheNearPlaneStayOnThePipeline) {
    const scene::MeshId sphere = add_mesh("sphere", geo::uv_sphere(1.0f, 96, 192));
    add_item(sphere);
    frame.camera.target = glm::dvec3(0.0);
    // The eye just outside the surface: the clusters under it are large on screen or reach
    // across the near plane; those far round the sphere are small.
    frame.camera.eye = glm::dvec3(0.0, 0.0, 1.12);
    const PrepassDepth close = expect_same_depth("close to the sphere");
    EXPECT_LT(close.computed, close.drawn);
    // Inside: every surface is the sphere's inside, back faces drawn.
    frame.camera.eye = glm::dvec3(0.0, 0.0, 0.3);
    frame.camera.target = glm::dvec3(0.0, 0.0, -1.0);
    expect_same_depth("inside the sphere");
    // A 12-triangle cube filling the view: nothing small.
    frame.items.clear();
    add_item(add_mesh("cube", geo::box(glm::vec3(1.0f))));
    frame.camera.eye = glm::dvec3(0.4, 0.5, 2.2);
    EXPECT_EQ(depth_with(render::PrepassRaster::compute).computed, 0u);
}

TEST_F(PrepassRasterTest, AutomaticTakesOnlyDenseMeshesOnASoftwareRasteriser) {
    add_item(add_mesh("cube", geo::box(glm::vec3(1.0f))));
    frame.camera.eye = glm::dvec3(3.0, 2.0, 4.0);
    frame.camera.target = glm::dvec3(0.0);
    EXPECT_EQ(depth_with(render::PrepassRaster::automatic).computed, 0u) << "12 triangles";
    frame.items.clear();
    add_item(add_mesh("sphere", geo::uv_sphere(1.0f, 128, 256)));  // 65k triangles, 320x240
    const PrepassDepth dense = depth_with(render::PrepassRaster::automatic);
    if (gl::is_software_renderer())
        EXPECT_GT(dense.computed, 0u);
    else
        EXPECT_EQ(dense.computed, 0u) << "a GPU's pipeline keeps its triangles";
}

TEST_F(PrepassRasterTest, RealModelsKeepTheirLines) {
    settings.method = render::LineMethod::compute;
    for (const char* path :
         {"/usr/share/assimp/models/BLEND/Suzanne_248.blend",
          "/usr/share/assimp/models/OBJ/spider.obj", "/usr/share/assimp/models/PLY/Wuson.ply"}) {
        show_model(path);
        expect_same_depth(path);
        settings.prepass_raster = render::PrepassRaster::pipeline;
        renderer->set_settings(settings);
        const Mask pipeline = mask();
        settings.prepass_raster = render::PrepassRaster::compute;
        renderer->set_settings(settings);
        const Mask compute = mask();
        expect_same_lines(pipeline, compute, path);
    }
}

}  // namespace
}  // namespace bz::test
