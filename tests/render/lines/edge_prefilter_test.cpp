// The CPU edge prefilter (render/lines/edge_prefilter.h): listing on the CPU the edges that
// may be feature edges, before edges.comp classifies them, must give the lines the shader
// alone gives - the same mask, the same picture, the same feature edges - on real models and
// on scenes made to put faces near grazing, in the styles that read the edge buffer; and it
// must list far fewer edges than the clusters hold.
#include "render/lines/edge_prefilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

class EdgePrefilterTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        use_repeatable_compute_frames();
    }
    // The picture, the mask and the feature edges with the prefilter off and on; the edges
    // edges.comp was given with it on, against off.
    void expect_same_lines(const std::string& what) {
        std::vector<std::uint8_t> pictures[2], masks[2];
        std::size_t features[2] = {0, 0}, tested[2] = {0, 0};
        for (const bool cpu : {false, true}) {
            settings.edge_prefilter = cpu ? render::EdgePrefilter::cpu : render::EdgePrefilter::gpu;
            settings.count_edges = true;
            renderer->set_settings(settings);
            // The count read back is that of the frame pass_times_latency() frames before.
            for (int i = 0; i <= renderer->pass_times_latency(); ++i)
                renderer->render(frame, meshes, render::Renderer::kOffscreen);
            pictures[cpu] = renderer->read_color();
            features[cpu] = renderer->stats().feature_edges;
            tested[cpu] = renderer->stats().edge_culling.edges_dispatched;
            masks[cpu] = renderer->render_mask(frame, meshes);
            EXPECT_EQ(renderer->stats().edge_culling.edges_prefiltered > 0, cpu) << what;
        }
        EXPECT_EQ(masks[0], masks[1]) << what << ": the mask changed";
        EXPECT_EQ(features[0], features[1]) << what << ": other feature edges";
        EXPECT_GT(features[1], 0u) << what;
        EXPECT_LE(tested[1], tested[0]) << what;
        std::size_t lines = 0;
        for (const std::uint8_t m : masks[1]) lines += m > 0;
        EXPECT_GT(lines, 100u) << what << ": nothing drawn, the comparison means nothing";
        // The beam adds the records in the order the shader appended them: a pixel may round
        // differently, no more.
        ASSERT_EQ(pictures[0].size(), pictures[1].size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < pictures[0].size(); ++i)
            differ += std::abs(int(pictures[0][i]) - int(pictures[1][i])) > 2;
        EXPECT_LE(differ, pictures[0].size() / 1000) << what << ": the picture changed";
    }
};

TEST_F(EdgePrefilterTest, RealModelsGiveTheSameLinesInTheEdgeBufferStyles) {
    for (const char* path : {"/usr/share/assimp/models/PLY/Wuson.ply",
                             "/usr/share/assimp/models/BLEND/Suzanne_248.blend",
                             "/usr/share/assimp/models/OBJ/spider.obj"}) {
        show_model(path);
        for (const scene::Style style :
             {scene::Style::vector, scene::Style::toon, scene::Style::technical}) {
            frame.style = style;
            expect_same_lines(std::string(path) + " style " + std::to_string(int(style)));
        }
    }
}

TEST_F(EdgePrefilterTest, GrazingSheetsMirroredInstancesAndTheEyeInside) {
    const scene::MeshId sphere = add_mesh("sphere", geo::uv_sphere(1.0f, 48, 96));
    const scene::MeshId sheet = add_mesh("sheet", geo::grid(20, 20, 0.1f, 20));
    frame.camera.target = glm::dvec3(0.0);
    // A sheet seen nearly edge-on from above and from below, beside a mirrored, stretched
    // sphere.
    for (const double y : {0.02, -0.02, 0.0}) {
        frame.items.clear();
        add_item(sheet);
        add_item(sphere, glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -3.0)),
                                    glm::dvec3(-1.0, 1.0, 1.5)));
        frame.camera.eye = glm::dvec3(0.3, y, 4.0);
        expect_same_lines("sheet at eye height " + std::to_string(y));
    }
    // The eye just above the sphere, looking along it to the horizon (0.2 away, beyond the
    // near plane): its faces are seen at grazing angles, and the float eye - vertex the shader
    // and the prefilter compute loses digits; the prefilter must still list what the shader
    // draws.
    frame.items.clear();
    add_item(sphere);
    frame.camera.eye = glm::dvec3(0.0, 1.02, 0.0);
    frame.camera.target = glm::dvec3(1.0, 0.82, 0.0);
    expect_same_lines("a hair above the sphere");
    // The eye inside a box: every face is seen from behind, the creases are the lines.
    const scene::MeshId box = add_mesh("box", geo::box(glm::vec3(1.0f)));
    frame.items.clear();
    add_item(box);
    frame.camera.eye = glm::dvec3(0.1, 0.2, 0.3);
    frame.camera.target = glm::dvec3(0.5, 0.3, -1.0);
    expect_same_lines("inside a box");
}

// The block test lists exactly the edges the edge-by-edge definition keeps, in order: faces
// both ways, near grazing on either side of the band, without face B, not-a-number, creases
// and keys above the threshold, in blocks that start anywhere and end short of a cluster.
TEST(EdgePrefilterBlock, ListsWhatMayBeFeatureKeeps) {
    std::vector<render::EdgeFacing> facings;
    std::vector<float> keys;
    const glm::vec3 eye(0.3f, 2.0f, -1.5f);
    std::uint32_t state = 12345u;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f * 2.0f - 1.0f;
    };
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 a(next(), next(), next());
        const glm::vec3 to_eye = eye - a;
        glm::vec3 n_a(next(), next(), next()), n_b(next(), next(), next());
        // Every fourth face lies within a few multiples of the band of grazing.
        if (i % 4 == 0)
            n_a -= to_eye * (glm::dot(n_a, to_eye) / glm::dot(to_eye, to_eye)) *
                   (1.0f - 1e-4f * next());
        if (i % 7 == 0) n_b = glm::vec3(0.0f);  // no face B
        if (i % 97 == 0) n_a.x = std::nanf("");
        facings.push_back({a, n_a, n_b});
        keys.push_back(i % 5 == 0 ? -0.9f : 0.4f + 0.2f * next());  // around the threshold
    }
    // A table of them, padded as build_edge_facing_table pads it.
    render::EdgeFacingTable table;
    table.edges = facings.size();
    for (std::size_t i = 0; i < facings.size() + geo::kMaxClusterEdges; ++i) {
        const bool pad = i >= facings.size();
        const render::EdgeFacing f = pad ? render::EdgeFacing{} : facings[i];
        const float values[] = {f.a.x,   f.a.y,   f.a.z,   f.n_a.x, f.n_a.y,
                                f.n_a.z, f.n_b.x, f.n_b.y, f.n_b.z, pad ? 2.0f : keys[i]};
        for (int c = 0; c < render::EdgeFacingTable::kColumns; ++c)
            table.columns[c].push_back(values[c]);
    }
    const float cos_crease = 0.5f;
    std::size_t kept_total = 0, dropped_total = 0;
    for (std::uint32_t first = 0; first < facings.size(); first += 37) {
        const auto count = static_cast<std::uint32_t>(
            std::min<std::size_t>({geo::kMaxClusterEdges, 1 + first % 64, facings.size() - first}));
        std::vector<std::uint32_t> expected;
        for (std::uint32_t e = first; e < first + count; ++e)
            if (render::may_be_feature(table.at(e), keys[e], eye, cos_crease))
                expected.push_back(e);
        std::vector<std::uint32_t> kept(geo::kMaxClusterEdges);
        kept.resize(render::list_maybe_features(table, first, count, eye, cos_crease, kept.data()));
        EXPECT_EQ(kept, expected) << "block at " << first;
        kept_total += kept.size();
        dropped_total += count - kept.size();
    }
    EXPECT_GT(kept_total, 100u);
    EXPECT_GT(dropped_total, 50u);
}

}  // namespace
}  // namespace bz::test
