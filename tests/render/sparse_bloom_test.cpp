// The sparse first downsample of the bloom (pass_bloom.cpp): the stages that build the beam's
// quads mark the screen tiles each quad may light (shaders/beam/beam_tiles.glsl), and the
// downsample reads the beam image only under those tiles. The frame must be the one the dense
// downsample gives, for scene lines drawn by either line method and for HUD lines, with
// diagonal, short and wide lines and lines running off the screen, in both beam looks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

#include "geometry/generated/primitives.h"
#include "gl/driver.h"
#include "render/render_fixture.h"
#include "render/targets.h"

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
    // balanced with `method` and the beam `look`, without the phosphor: one frame, no history.
    static bz::render::RenderSettings one_frame_settings(bz::render::LineMethod method,
                                                         const char* look) {
        auto s = bz::render::preset("balanced");
        s.method = method;
        s.beam = bz::render::beam_look(look);
        s.beam.phosphor = bz::render::PhosphorDecay::off;
        return s;
    }
    std::vector<std::uint8_t> render_with(bz::render::RenderSettings s, bool sparse) {
        s.sparse_composite = sparse;
        settings = s;
        renderer->set_settings(s);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        return renderer->read_color();
    }
};

// Two RGBA8 frames at most one 8-bit step apart (the additive beam's thread order), and the
// second one lit enough to tell.
void expect_same_lit_picture(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                             const char* differ) {
    ASSERT_EQ(a.size(), b.size());
    int worst = 0;
    std::size_t lit = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        worst = std::max(worst, std::abs(int{a[i]} - int{b[i]}));
        if (i % 4 != 3 && b[i] > 0) ++lit;
    }
    EXPECT_LE(worst, 1) << differ;
    EXPECT_GT(lit, b.size() / 50) << "the frame holds too little to compare";
}

}  // namespace

TEST_F(SparseBloomTest, TheBeamsTileMarksCoverEveryLitBlockInBothMethodsAndLooks) {
    for (const auto method : bz::render::feature_line_methods()) {
        for (const char* look : {"classic", "mame"}) {
            SCOPED_TRACE(std::string(bz::render::line_method_name(method)) + ", " + look);
            auto s = one_frame_settings(method, look);
            const auto sparse = render_with(s, true);
            const auto dense = render_with(s, false);
            expect_same_lit_picture(sparse, dense, "the sparse downsample missed light");
        }
    }
}

// RenderSettings::first_downsample: without the beam's tile marks the downsample reads the
// whole beam image; the picture is the same, in both methods and looks, and the composite's
// own lit tiles (marked by the downsample either way) still cover it.
TEST_F(SparseBloomTest, TheWholeImageDownsampleGivesTheMarkedTilesPicture) {
    for (const auto method : bz::render::feature_line_methods()) {
        for (const char* look : {"classic", "mame"}) {
            SCOPED_TRACE(std::string(bz::render::line_method_name(method)) + ", " + look);
            auto s = one_frame_settings(method, look);
            s.first_downsample = bz::render::FirstDownsample::sparse;
            const auto marked = render_with(s, true);
            EXPECT_EQ(renderer->stats().first_downsample,
                      bz::render::FirstDownsampleRead::marked_tiles);
            s.first_downsample = bz::render::FirstDownsample::dense;
            const auto whole = render_with(s, true);
            EXPECT_EQ(renderer->stats().first_downsample,
                      bz::render::FirstDownsampleRead::whole_image);
            expect_same_lit_picture(marked, whole, "the two downsamples differ");
        }
    }
}

// Automatic reads the whole image on a software rasteriser when the frame before listed half
// the screen's tiles or more (a screen full of spheres), and keeps the marks where it listed
// fewer (the few spheres of the fixture); a GPU keeps them always.
TEST_F(SparseBloomTest, AutomaticReadsTheWholeImageWhereHalfTheTilesWereLit) {
    auto s = bz::render::preset("balanced");
    s.beam = bz::render::beam_look("mame");
    s.first_downsample = bz::render::FirstDownsample::automatic;
    constexpr int kTile = bz::render::kLitTileSize;
    const std::size_t tiles =
        static_cast<std::size_t>((kWidth + kTile - 1) / kTile) * ((kHeight + kTile - 1) / kTile);
    auto share_then_choice = [&] {
        render_with(s, true);  // the frame before: its list is the one the next frame reads
        const double share =
            static_cast<double>(renderer->read_lit_tiles().size()) / static_cast<double>(tiles);
        render_with(s, true);
        return std::pair{share, renderer->stats().first_downsample};
    };
    const auto [few_share, few_choice] = share_then_choice();
    EXPECT_LT(few_share, 0.5);
    EXPECT_EQ(few_choice, bz::render::FirstDownsampleRead::marked_tiles);
    // A grid of coarse spheres over the whole view.
    const bz::scene::MeshId ball = add_mesh("ball", bz::geo::uv_sphere(0.22f, 6, 10));
    for (int y = -3; y <= 3; ++y)
        for (int x = -4; x <= 4; ++x)
            add_item(ball, glm::translate(glm::dmat4(1.0), {0.55 * x, 0.55 * y, 0.0}));
    const auto [many_share, many_choice] = share_then_choice();
    EXPECT_GE(many_share, 0.5);
    EXPECT_EQ(many_choice, bz::gl::is_software_renderer()
                               ? bz::render::FirstDownsampleRead::whole_image
                               : bz::render::FirstDownsampleRead::marked_tiles);
}
