// Colour clears by a compute shader (render/clear_image.h) leave what glClear leaves: the
// picture and the mask of every style, and of the image-space outline, are the same byte for
// byte with either path, for a frame drawn straight after a different one (a clear that missed
// a texel would show the frame before).
#include "render/clear_image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "render/programs.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

class ColourClearsTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        use_repeatable_compute_frames();
        show_model("/usr/share/assimp/models/OBJ/spider.obj");
        // The frame before: the same model seen from elsewhere, so its lines, fills and
        // strokes lie where this frame's do not.
        before = frame;
        before.camera.eye = frame.camera.target +
                            (frame.camera.eye - frame.camera.target) * glm::dvec3(-0.6, 1.4, 0.7);
    }

    // This frame's picture and mask after `before`, with each clear path: the same bytes, or
    // within `tolerance` of them.
    void expect_same_frames(const std::string& what, int tolerance = 0) {
        std::vector<std::uint8_t> pictures[2], masks[2];
        std::size_t k = 0;
        for (const render::ColourClears clears :
             {render::ColourClears::pipeline, render::ColourClears::compute}) {
            settings.colour_clears = clears;
            renderer->set_settings(settings);
            before.style = frame.style;
            renderer->render(before, meshes, render::Renderer::kOffscreen);
            renderer->render_mask(before, meshes);
            renderer->render(frame, meshes, render::Renderer::kOffscreen);
            pictures[k] = renderer->read_color();
            masks[k] = renderer->render_mask(frame, meshes);
            ++k;
        }
        ASSERT_EQ(pictures[0].size(), pictures[1].size());
        int worst = 0;
        for (std::size_t i = 0; i < pictures[0].size(); ++i)
            worst = std::max(worst, std::abs(int(pictures[0][i]) - int(pictures[1][i])));
        EXPECT_LE(worst, tolerance) << what << ": the picture differs";
        EXPECT_EQ(masks[0], masks[1]) << what << ": the mask differs";
        std::size_t lines = 0;
        for (const std::uint8_t m : masks[1]) lines += m > 0;
        EXPECT_GT(lines, 100u) << what << ": nothing drawn, the comparison means nothing";
    }

    scene::FrameList before;
};

TEST_F(ColourClearsTest, AutomaticMeasuresOnAHardwareGpuOnly) {
    render::RenderSettings s;
    EXPECT_EQ(s.colour_clears, render::ColourClears::automatic);
    EXPECT_EQ(render::clear_path(s, true), render::ClearPath::pipeline);
    EXPECT_EQ(render::clear_path(s, false), render::ClearPath::measure);
    s.colour_clears = render::ColourClears::compute;
    EXPECT_EQ(render::clear_path(s, true), render::ClearPath::compute);
    s.colour_clears = render::ColourClears::pipeline;
    EXPECT_EQ(render::clear_path(s, false), render::ClearPath::pipeline);
    // This machine's software rasteriser takes glClear without timing anything; a forced
    // path is taken as it is.
    settings.colour_clears = render::ColourClears::automatic;
    renderer->set_settings(settings);
    renderer->render(frame, meshes, render::Renderer::kOffscreen);
    EXPECT_FALSE(renderer->colour_clears_by_compute());
    EXPECT_FALSE(renderer->colour_clear_timing().has_value());
    settings.colour_clears = render::ColourClears::compute;
    renderer->set_settings(settings);
    EXPECT_TRUE(renderer->colour_clears_by_compute());
}

// The timing the GPU's choice rests on runs its two clears and reads two times back (on a
// software rasteriser the times mean little, but the calls are the GPU's own).
TEST_F(ColourClearsTest, TimingBothPathsReadsTwoTimes) {
    const render::Programs programs = render::load_programs(settings);
    const render::ClearTiming t = render::time_colour_clears(programs.clear_image, 64, 48);
    EXPECT_GE(t.pipeline_ms, 0.0);
    EXPECT_GE(t.compute_ms, 0.0);
    EXPECT_LT(t.pipeline_ms, 1000.0);
    EXPECT_LT(t.compute_ms, 1000.0);
}

TEST_F(ColourClearsTest, EveryStyleDrawsTheSameFrameWithEitherPath) {
    for (const scene::Style style : scene::all_styles()) {
        frame.style = style;
        expect_same_frames("style " + std::string(scene::style_name(style)));
    }
}

TEST_F(ColourClearsTest, TheMipChainBloomAndTheImageOutlineToo) {
    frame.style = scene::Style::vector;
    settings.beam = render::beam_look("mame");
    // Frames that repeat exactly: no history kept, no flicker from frame to frame.
    settings.beam.phosphor = render::PhosphorDecay::off;
    settings.beam.flicker = 0.0f;
    // Its additive beam sums overlapping quads in whatever order the rasteriser's threads take
    // them: a channel may round one step apart between any two runs, clears aside, and two
    // where the glow's 32-bit chain (BloomChainTest) carries that difference to a faint edge
    // (seen once in 36 runs).
    expect_same_frames("mame beam, mip-chain bloom", 2);
    settings = render::preset("balanced");
    settings.beam = render::beam_look("classic");
    settings.method = render::LineMethod::image_outline;
    expect_same_frames("image-space outline");
}

}  // namespace
}  // namespace bz::test
