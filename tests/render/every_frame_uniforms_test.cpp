// gl::Program reports a uniform set by a name its program's source does not declare as a GL
// error. Every pass of every style, line method and beam look runs here, so a pass that sets a
// misspelled, renamed or foreign uniform fails this test, combination by combination.
#include <gtest/gtest.h>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"
#include "scene/style.h"

namespace {

// Colour over a few frames (the phosphor and glow history), the HUD, and the mask.
class EveryFrameUniformsTest : public bz::test::RenderTest {};

TEST_F(EveryFrameUniformsTest, NoPassSetsAnUndeclaredUniform) {
    const auto cube = add_mesh("cube", bz::geo::box(glm::vec3(1.0f)));
    add_item(cube);
    frame.camera.eye = {2.5, 2.0, 3.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.hud.push_back({{-0.8f, 0.8f}, {0.8f, 0.8f}, {1.0f, 0.2f, 0.2f}, 1.0f});
    auto& sink = context().debug();
    int combinations = 0;
    for (const auto& look : bz::render::beam_look_names()) {
        for (const auto method :
             {bz::render::LineMethod::geometry_shader, bz::render::LineMethod::compute,
              bz::render::LineMethod::image_outline}) {
            for (const auto style : bz::scene::all_styles()) {
                bz::render::RenderSettings s = bz::render::preset("balanced");
                s.method = method;
                s.beam = bz::render::beam_look(look);
                renderer->set_settings(s);
                frame.style = style;
                for (int f = 0; f < 3; ++f) {
                    frame.time_s = f / 60.0;
                    renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
                }
                renderer->render_mask(frame, meshes);
                const std::string what = std::string(bz::scene::style_name(style)) + " / " +
                                         bz::render::line_method_name(method) + " / " + look;
                EXPECT_EQ(sink.error_count(), 0) << what;
                for (const auto& m : sink.messages()) ADD_FAILURE() << what << ": " << m;
                sink.clear();
                ++combinations;
            }
        }
    }
    EXPECT_EQ(combinations, static_cast<int>(bz::render::beam_look_names().size() * 3 *
                                             bz::scene::all_styles().size()));
}

}  // namespace
