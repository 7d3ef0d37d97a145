// Culling triangle clusters in the prepass and the fills (render/gpu_scene/triangle_culling.h)
// draws only what would be clipped or back-face culled anyway: the frame must be the one whole
// meshes give, byte for byte, on real models, in every style, from outside and inside.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

class ClusterCullingTest : public RenderTest {
  protected:
    // The picture and the mask with cluster culling on and off.
    void expect_same_frames(const std::string& what) {
        std::vector<std::uint8_t> pictures[2], masks[2];
        for (const bool cull : {false, true}) {  // culling last: its stats stay
            settings.cluster_culling = cull;
            renderer->set_settings(settings);
            renderer->render(frame, meshes, render::Renderer::kOffscreen);
            pictures[cull] = renderer->read_color();
            masks[cull] = renderer->render_mask(frame, meshes);
        }
        EXPECT_EQ(pictures[0], pictures[1]) << what << ": the picture changed";
        EXPECT_EQ(masks[0], masks[1]) << what << ": the mask changed";
        std::size_t lines = 0;
        for (const std::uint8_t m : masks[1]) lines += m > 0;
        EXPECT_GT(lines, 100u) << what << ": nothing drawn, the comparison means nothing";
    }
};

TEST_F(ClusterCullingTest, RealModelsDrawTheSameFrameInEveryStyle) {
    settings.beam = render::beam_look("classic");  // no flicker: frames repeat exactly
    for (const char* path : {"/usr/share/assimp/models/PLY/Wuson.ply",
                             "/usr/share/assimp/models/BLEND/Suzanne_248.blend",
                             "/usr/share/assimp/models/OBJ/spider.obj"}) {
        show_model(path);
        for (const scene::Style style :
             {scene::Style::vector, scene::Style::toon, scene::Style::halo}) {
            frame.style = style;
            expect_same_frames(std::string(path) + " style " + std::to_string(int(style)));
        }
    }
}

TEST_F(ClusterCullingTest, AModelCutByTheFrustumAndSeenFromInside) {
    settings.beam = render::beam_look("classic");
    show_model("/usr/share/assimp/models/BLEND/Suzanne_248.blend");
    frame.style = scene::Style::vector;
    // Close up: the head overfills the view, clusters lie outside it and across its edges.
    const scene::Camera framed = frame.camera;
    frame.camera.eye = framed.target + (framed.eye - framed.target) * 0.3;
    expect_same_frames("close up");
    EXPECT_GT(renderer->stats().triangle_culling.outside_frustum, 0u);
    // The eye inside the head: nothing may be skipped as facing away.
    frame.camera.eye = framed.target;
    frame.camera.target = framed.target + glm::dvec3(0.0, 0.0, -1.0);
    settings.cluster_culling = true;
    renderer->set_settings(settings);
    renderer->render(frame, meshes, render::Renderer::kOffscreen);
    EXPECT_EQ(renderer->stats().triangle_culling.facing_away, 0u);
}

// One mesh of an open sheet and closed boxes (a hallway's panels around its pipes): the boxes'
// clusters skip their back faces where the eye is outside their pieces' box, and the frame
// stays the one the whole mesh, drawn two-sided, gives - from above, from under the sheet,
// and from inside a box, whose own clusters must then keep both faces.
TEST_F(ClusterCullingTest, ClosedPiecesOfAnOpenMeshSkipTheirBackFaces) {
    settings.beam = render::beam_look("classic");
    geo::TriMesh m = geo::grid(20, 20, 0.5f, 20);
    const geo::TriMesh solid = geo::box(glm::vec3(0.6f));  // its creases show from inside too
    for (int i = 0; i < 9; ++i) {
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        const glm::vec3 at(float(i % 3) * 3.0f - 3.0f, 1.0f, float(i / 3) * 3.0f - 3.0f);
        for (const glm::vec3& p : solid.positions) m.positions.push_back(p + at);
        for (const std::uint32_t v : solid.indices) m.indices.push_back(base + v);
    }
    const scene::MeshId id = add_mesh("panels and boxes", m);
    frame.items.clear();
    add_item(id);
    frame.camera.target = glm::dvec3(0.0, 0.5, 0.0);
    struct View {
        const char* what;
        glm::dvec3 eye, target;
    };
    for (const View& v : {View{"above", {4.0, 6.0, 7.0}, {0.0, 0.5, 0.0}},
                          View{"under the sheet", {1.0, -3.0, 6.0}, {0.0, 0.5, 0.0}},
                          View{"inside a box", {0.05, 1.1, -0.1}, {3.0, 1.0, 3.0}}}) {
        frame.camera.eye = v.eye;
        frame.camera.target = v.target;
        for (const scene::Style style : {scene::Style::vector, scene::Style::toon}) {
            frame.style = style;
            expect_same_frames(std::string(v.what) + " style " + std::to_string(int(style)));
            const std::size_t one_sided = renderer->stats().triangle_culling.one_sided;
            // From inside a box, culling its back faces would hide its inside and change the
            // frame; its cluster (all nine boxes, 108 triangles) stays two-sided there.
            if (v.eye.y > 1.6 || v.eye.y < 0.0)
                EXPECT_GT(one_sided, 0u) << v.what;
            else
                EXPECT_EQ(one_sided, 0u) << v.what;
        }
    }
}

TEST_F(ClusterCullingTest, ManyInstancesCullOnSeveralThreadsAndDrawTheSameFrame) {
    // 160 spheres of 130 triangle clusters and about 380 edge clusters each: past the point
    // where culling runs on several threads (pass_prepass.cpp, pass_edges.cpp).
    settings.beam = render::beam_look("classic");
    settings.method = render::LineMethod::compute;
    const scene::MeshId id = add_mesh("sphere", geo::uv_sphere(0.4f, 64, 128));
    frame.items.clear();
    for (int i = 0; i < 160; ++i) {
        add_item(id, glm::translate(glm::dmat4(1.0), glm::dvec3(i % 16 - 7.5, i / 16 - 4.5, 0.0)));
    }
    frame.camera.eye = glm::dvec3(0.0, 0.0, 14.0);
    frame.camera.target = glm::dvec3(0.0);
    frame.style = scene::Style::vector;
    expect_same_frames("160 spheres");
    const auto& stats = renderer->stats();
    EXPECT_GE(stats.triangle_culling.clusters, 16384u);
    EXPECT_GE(stats.edge_culling.clusters, 16384u);
    EXPECT_GT(stats.triangle_culling.facing_away, 0u);
}

}  // namespace
}  // namespace bz::test
