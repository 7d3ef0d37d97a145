// The sparse first downsample of the bloom (pass_bloom.cpp): the stages that build the beam's
// quads mark the screen tiles each quad may light (shaders/beam/beam_tiles.glsl), and the
// downsample reads the beam image only under those tiles. The frame must be the one the dense
// downsample gives, for scene lines drawn by either line method and for HUD lines, with
// diagonal, short and wide lines and lines running off the screen, in both beam looks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

using bz::test::RenderTest;

namespace {

class SparseBloomTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        // Coarse spheres spread over the view, one past its left edge, and a long thin bar
        // across it diagonally: silhouettes and creases at every angle and length.
        add_item(add_mesh("sphere", bz::geo::uv_sphere(0.35f, 6, 10)));
        add_item(frame.items.back().mesh, glm::translate(glm::dmat4(1.0), {-1.9, 0.6, -0.5}));
        add_item(frame.items.back().mesh, glm::translate(glm::dmat4(1.0), {1.2, -0.7, 0.3}));
        add_item(frame.items.back().mesh, glm::translate(glm::dmat4(1.0), {0.3, 0.9, -1.0}));
        add_item(add_mesh("bar", bz::geo::box({1.8f, 0.02f, 0.02f})),
                 glm::rotate(glm::dmat4(1.0), 0.5, {0.0, 0.0, 1.0}));
        frame.camera.eye = {0.0, 0.0, 4.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        // A HUD line near the bottom edge and a dot near a corner; a line along the first pixel
        // row of a tile row, whose width spills into the row of tiles below it, and one along
        // the first pixel column of a tile column.
        frame.hud.push_back({{-1.2f, -0.95f}, {0.9f, -0.97f}, {0.2f, 1.0f, 0.2f}, 1.2f});
        frame.hud.push_back({{1.25f, 0.93f}, {1.25f, 0.93f}, {0.2f, 1.0f, 0.2f}, 0.8f});
        const float half = kHeight * 0.5f;
        const float row_y = (96.5f - half) / half;               // window row 96 = 3 * 32
        const float column_x = (224.5f - kWidth * 0.5f) / half;  // window column 224 = 7 * 32
        frame.hud.push_back({{-0.9f, row_y}, {-0.2f, row_y}, {0.2f, 1.0f, 0.2f}, 1.5f});
        frame.hud.push_back({{column_x, 0.1f}, {column_x, 0.6f}, {0.2f, 1.0f, 0.2f}, 1.5f});
    }
    std::vector<std::uint8_t> render_with(bz::render::RenderSettings s, bool sparse) {
        s.sparse_composite = sparse;
        settings = s;
        renderer->set_settings(s);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        return renderer->read_color();
    }
};

}  // namespace

TEST_F(SparseBloomTest, TheBeamsTileMarksCoverEveryLitBlockInBothMethodsAndLooks) {
    for (const auto method : bz::render::feature_line_methods()) {
        for (const char* look : {"classic", "mame"}) {
            SCOPED_TRACE(std::string(bz::render::line_method_name(method)) + ", " + look);
            auto s = bz::render::preset("balanced");
            s.method = method;
            s.beam = bz::render::beam_look(look);
            s.beam.phosphor = bz::render::PhosphorDecay::off;  // one frame, no history
            const auto sparse = render_with(s, true);
            const auto dense = render_with(s, false);
            ASSERT_EQ(sparse.size(), dense.size());
            int worst = 0;
            std::size_t lit = 0;
            for (std::size_t i = 0; i < dense.size(); ++i) {
                worst = std::max(worst, std::abs(int{sparse[i]} - int{dense[i]}));
                if (i % 4 != 3 && dense[i] > 0) ++lit;
            }
            EXPECT_LE(worst, 1) << "the sparse downsample missed light";
            EXPECT_GT(lit, dense.size() / 50) << "the frame holds too little to compare";
        }
    }
}
