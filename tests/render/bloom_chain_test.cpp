// The mip-chain bloom's levels past the first, walked by one compute workgroup
// (BloomChain::compute, shaders/beam/bloom_chain.comp), against one draw per level each way
// (BloomChain::pipeline): the same glow. The compute path keeps the levels in 32-bit floats;
// the pipeline's RGBA16F targets round every level it writes, so the two may differ by that
// rounding, summed over the chain, and no more: a level missed, read before it was written or
// weighted wrongly moves the glow by far more than the bounds below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "gl/driver.h"
#include "render/render_fixture.h"

namespace bz::test {
namespace {

// The finished bloom's texel back in linear light (shaders/beam/bloom_encoding.glsl).
double decode(std::uint8_t encoded) {
    const double e = encoded / 255.0;
    return e * e * 4.0;
}

struct Frame {
    std::vector<std::uint8_t> bloom;  // encoded 8-bit, at the bloom's resolution
    std::vector<std::uint8_t> picture;
};

class BloomChainTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        show_model("/usr/share/assimp/models/OBJ/spider.obj");
        settings = render::preset("balanced");
        settings.beam = render::beam_look("mame");
        // Frames that repeat exactly: no history, no flicker.
        settings.beam.phosphor = render::PhosphorDecay::off;
        settings.beam.flicker = 0.0f;
    }

    Frame draw(render::BloomChain chain) {
        settings.bloom_chain = chain;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, render::Renderer::kOffscreen);
        Frame f;
        glm::ivec2 size{};
        f.bloom = renderer->read_bloom(&size);
        f.picture = renderer->read_color();
        return f;
    }

    // Both paths at this size and with these weights: the same glow within the rounding of
    // half floats, and a picture at most a few steps apart in its faintest glow.
    void expect_same_glow(const std::string& what) {
        SCOPED_TRACE(what);
        const Frame pipeline = draw(render::BloomChain::pipeline);
        const Frame compute = draw(render::BloomChain::compute);
        ASSERT_EQ(pipeline.bloom.size(), compute.bloom.size());
        double sum_pipeline = 0.0, sum_compute = 0.0, worst = 0.0;
        std::size_t lit = 0;
        for (std::size_t i = 0; i < pipeline.bloom.size(); i += 4) {
            for (std::size_t c = 0; c < 3; ++c) {
                const std::uint8_t a = pipeline.bloom[i + c], b = compute.bloom[i + c];
                sum_pipeline += decode(a);
                sum_compute += decode(b);
                // What one 8-bit step is worth at the brighter of the two, in linear light.
                const double step =
                    decode(static_cast<std::uint8_t>(std::min(255, std::max(a, b) + 1))) -
                    decode(std::max(a, b));
                const double off = std::abs(decode(a) - decode(b));
                worst = std::max(worst, off / (0.005 * std::max(decode(a), decode(b)) + step));
            }
            lit += std::max({pipeline.bloom[i], pipeline.bloom[i + 1], pipeline.bloom[i + 2]}) > 0;
        }
        EXPECT_GT(lit, pipeline.bloom.size() / 4 / 40) << "too little glow to compare";
        EXPECT_NEAR(sum_compute / sum_pipeline, 1.0, 0.005);
        EXPECT_LE(worst, 1.0) << "a texel differs by more than half a percent and a step";
        int steps = 0;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < pipeline.picture.size(); ++i) {
            const int d = std::abs(int(pipeline.picture[i]) - int(compute.picture[i]));
            steps = std::max(steps, d);
            differing += d > 0;
        }
        // The glow's faintest edge goes through the black level, the 8-bit square-root
        // encoding and the gamma curve, each steepest near black.
        EXPECT_LE(steps, 4);
        EXPECT_LT(differing, pipeline.picture.size() / 20);
    }
};

// 320x240 at a quarter: levels 80x60, 40x30, 20x15, then 10x7 and 5x3, whose halving is not
// exact, down to 2x1 (the chain stops before 1x1).
TEST_F(BloomChainTest, EveryLevelOfTheMameChain) {
    expect_same_glow("mame weights, 320x240");
}

TEST_F(BloomChainTest, OddSizesAndAChainOfTwoLevels) {
    renderer->resize(333, 197);
    expect_same_glow("333x197 (83x49 at a quarter)");
    settings.beam.mip_weights = {1.0f, 0.8f};
    expect_same_glow("two levels");
    settings.beam.mip_weights = {1.0f, 0.5f, 0.3f};
    expect_same_glow("three levels");
}

// A level past the first too large to walk on one thread (160x120 from a full-resolution
// bloom at 320x240) is drawn; the walk starts below it, and the draws go back up from there.
TEST_F(BloomChainTest, LargeLevelsDrawnTheRestWalked) {
    settings.bloom_resolution = render::BloomResolution::full;
    expect_same_glow("full-resolution bloom, 320x240");
    settings.beam.mip_weights = {1.0f, 0.8f};
    expect_same_glow("full resolution, two levels: nothing walked");
}

// The frame's stats say which levels past level 0 were drawn and which walked.
TEST_F(BloomChainTest, TheStatsSayWhichLevelsWereWalked) {
    // 320x240 at a quarter: 5 levels past level 0 (40x30 .. 2x1; the chain stops before
    // 1x1), all small.
    draw(render::BloomChain::compute);
    EXPECT_EQ(renderer->stats().bloom_chain.drawn, 0u);
    EXPECT_EQ(renderer->stats().bloom_chain.walked, 5u);
    draw(render::BloomChain::pipeline);
    EXPECT_EQ(renderer->stats().bloom_chain.drawn, 5u);
    EXPECT_EQ(renderer->stats().bloom_chain.walked, 0u);
    // At full resolution level 1 (160x120) is too large to walk; 80x60 .. 2x1 are walked.
    settings.bloom_resolution = render::BloomResolution::full;
    draw(render::BloomChain::compute);
    EXPECT_EQ(renderer->stats().bloom_chain.drawn, 1u);
    EXPECT_EQ(renderer->stats().bloom_chain.walked, 6u);
    // The Gaussian bloom has no chain.
    settings.beam = render::beam_look("classic");
    draw(render::BloomChain::compute);
    EXPECT_EQ(renderer->stats().bloom_chain.drawn + renderer->stats().bloom_chain.walked, 0u);
}

// Compute on a software rasteriser, the pipeline on a GPU: the same bytes as that path.
TEST_F(BloomChainTest, AutomaticTakesComputeOnASoftwareRasteriser) {
    EXPECT_EQ(render::RenderSettings{}.bloom_chain, render::BloomChain::automatic);
    const render::BloomChain expected =
        gl::is_software_renderer() ? render::BloomChain::compute : render::BloomChain::pipeline;
    const Frame chosen = draw(expected);
    const Frame automatic = draw(render::BloomChain::automatic);
    EXPECT_EQ(chosen.bloom, automatic.bloom);
    EXPECT_EQ(chosen.picture, automatic.picture);
}

}  // namespace
}  // namespace bz::test
