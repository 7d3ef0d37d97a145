// FrameList::view_top keeps the scene's lines under the HUD band: the rows above it stay dark,
// the rows below draw as before, and the HUD itself still draws there.
#include <gtest/gtest.h>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

class ViewTopTest : public RenderTest {
  protected:
    // A tall box straight ahead, filling most of the screen's height.
    void SetUp() override {
        RenderTest::SetUp();
        add_item(add_mesh("tall", geo::box({1.0f, 3.0f, 1.0f})));
        frame.camera.eye = {0.0, 0.0, 6.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 70.0;
    }
    // Lit pixels in rows [first, last) of the image (row 0 on top).
    int lit_rows(const std::vector<std::uint8_t>& rgba, int first, int last) const {
        int n = 0;
        for (int y = first; y < last; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const std::size_t i = static_cast<std::size_t>((y * kWidth + x) * 4);
                n += std::max({rgba[i], rgba[i + 1], rgba[i + 2]}) > 40 ? 1 : 0;
            }
        }
        return n;
    }
    std::vector<std::uint8_t> color() {
        renderer->render(frame, meshes, render::Renderer::kOffscreen);
        return renderer->read_color();
    }
};

TEST_F(ViewTopTest, SceneStaysUnderTheBand) {
    const std::vector<std::uint8_t> whole = color();
    save_color("view_top_whole");
    // The band: the top quarter of the screen (NDC y above 0.5). Bloom may spill a few rows
    // over the edge, so the rows next to it are not counted.
    const int band_rows = kHeight / 4;
    const int margin = 8;
    ASSERT_GT(lit_rows(whole, 0, band_rows - margin), 50) << "the box must reach into the band";
    frame.view_top = 0.5f;
    const std::vector<std::uint8_t> clipped = color();
    save_color("view_top_clipped");
    EXPECT_EQ(lit_rows(clipped, 0, band_rows - margin), 0);
    // Below the band nothing changes, but for the glow that no longer spills down from above.
    const int below = lit_rows(whole, band_rows + margin, kHeight);
    EXPECT_GT(below, 1000);
    EXPECT_NEAR(lit_rows(clipped, band_rows + margin, kHeight), below, below / 200);
    // HUD lines still draw in the band.
    frame.hud.push_back({{-0.5f, 0.8f}, {0.5f, 0.8f}, {1.0f, 0.3f, 0.2f}, 1.0f});
    EXPECT_GT(lit_rows(color(), 0, band_rows - margin), 50);
}

}  // namespace
}  // namespace bz::test
