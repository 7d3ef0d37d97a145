// The edges pass (render/lines/pass_edges.cpp) writes the records' face and vertex normals only
// for the styles whose strokes read them (records_carry_normals: the sketch weighs creases by
// how lit their faces are, the halo bends silhouettes by the vertex normals); every other
// frame leaves them out. Checked on the records themselves, read back after a frame of each
// style, with the CPU prefilter's listed edges and with whole clusters.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geometry/generated/primitives.h"
#include "render/camera/camera_framing.h"
#include "render/passes.h"
#include "render/render_fixture.h"
#include "render/styles/style_def.h"
#include "scene/style.h"

namespace bz::test {
namespace {

using scene::Style;

class PassEdgesTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        const scene::MeshId sphere = add_mesh("sphere", geo::uv_sphere(1.0f, 24, 48));
        add_item(sphere);
        frame.items.back().smooth = true;
        frame.camera = render::frame_bounds(meshes.bounds(sphere), 50.0, double(kWidth) / kHeight);
        settings.method = render::LineMethod::compute;
    }

    std::vector<render::EdgeRecord> records_of(Style style, render::EdgePrefilter prefilter) {
        frame.style = style;
        settings.edge_prefilter = prefilter;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, render::Renderer::kOffscreen);
        return renderer->read_edge_records();
    }
};

bool unit(const glm::vec4& v) {
    return std::abs(glm::length(glm::vec3(v)) - 1.0f) < 1e-3f && v.w == 0.0f;
}

TEST_F(PassEdgesTest, OnlyTheShadingStrokesAskForNormals) {
    EXPECT_TRUE(render::records_carry_normals(render::style_def(Style::sketch)));
    EXPECT_TRUE(render::records_carry_normals(render::style_def(Style::halo)));
    for (const Style style : scene::all_styles()) {
        if (style == Style::sketch || style == Style::halo) continue;
        EXPECT_FALSE(render::records_carry_normals(render::style_def(style)))
            << scene::style_name(style);
    }
}

TEST_F(PassEdgesTest, RecordsOfTheShadingStrokesCarryUnitNormals) {
    for (const Style style : {Style::sketch, Style::halo}) {
        for (const auto prefilter : {render::EdgePrefilter::cpu, render::EdgePrefilter::gpu}) {
            SCOPED_TRACE(std::string(scene::style_name(style)) +
                         (prefilter == render::EdgePrefilter::cpu ? ", listed" : ", clusters"));
            // A vector frame first, which leaves the normals out of the same buffer.
            ASSERT_FALSE(records_of(Style::vector, prefilter).empty());
            const std::vector<render::EdgeRecord> records = records_of(style, prefilter);
            // The sphere's outline: one silhouette edge per segment or so.
            ASSERT_GE(records.size(), 40u);
            for (std::size_t i = 0; i < records.size(); ++i) {
                const render::EdgeRecord& r = records[i];
                // A closed sphere: every feature edge is a silhouette with both faces.
                EXPECT_TRUE(unit(r.normal_a)) << "record " << i;
                EXPECT_TRUE(unit(r.normal_b)) << "record " << i;
                EXPECT_TRUE(unit(r.vertex_normal_a)) << "record " << i;
                EXPECT_TRUE(unit(r.vertex_normal_b)) << "record " << i;
            }
        }
    }
}

}  // namespace
}  // namespace bz::test
