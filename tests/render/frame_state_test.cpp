// A frame's state as data, on the GPU: the targets a renderer allocates follow the pass lists
// of the styles it drew (frame_passes.h), and the view's history follows its rules
// (frame_history.h). Prints the bytes each style's targets take at 1280x720, against the
// allocation of every image whatever the style (what the renderer did before, 2026-11-27).
#include <gtest/gtest.h>

#include <cstdio>

#include "geometry/generated/primitives.h"
#include "render/frame_passes.h"
#include "render/render_fixture.h"
#include "render/styles/style_def.h"
#include "render/targets.h"

namespace {

using bz::render::Resource;
using bz::render::ResourceSet;
using bz::scene::Style;

// Every image the renderer allocated before frames named theirs: all but the normals
// (image_outline only), with the phosphor's history when the look has one; and the occlusion
// layers that technical and vector-xray have peeled since.
std::size_t every_image_bytes(int w, int h, const bz::render::RenderSettings& s) {
    const ResourceSet all{Resource::depth,       Resource::lines,     Resource::beam_tiles,
                          Resource::bloom_chain, Resource::bloom_out, Resource::lit_tiles,
                          Resource::tile_list,   Resource::canvas,    Resource::shrunk_depth,
                          Resource::halo,        Resource::mask,      Resource::target};
    const ResourceSet with_layers = all | ResourceSet{Resource::peel_layers};
    std::size_t bytes = bz::render::allocated_bytes(bz::render::make_targets(w, h, s, with_layers));
    if (s.beam.phosphor != bz::render::PhosphorDecay::off) {
        const std::size_t lit = static_cast<std::size_t>((w + 15) / 16) * ((h + 15) / 16);
        const glm::ivec2 b = bz::render::bloom_size(w, h, s);
        bytes += std::size_t(w) * h * 8 + lit + std::size_t(b.x) * b.y * 4;
    }
    return bytes;
}

class FrameStateTest : public bz::test::RenderTest {
  protected:
    void SetUp() override {
        settings = bz::render::preset("balanced");
        settings.method = bz::render::LineMethod::geometry_shader;
        RenderTest::SetUp();
        add_item(add_mesh("cube", bz::geo::box(glm::vec3(0.5f))));
        frame.camera.eye = {1.5, 1.2, 2.5};
        frame.camera.target = {0, 0, 0};
    }
    void draw(Style style) {
        frame.style = style;
        frame.time_s += 1.0 / 60.0;
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
    }
};

TEST_F(FrameStateTest, EachStyleAllocatesOnlyWhatItsPassesUse) {
    for (const std::string beam : {"classic", "mame"}) {
        settings.beam = bz::render::beam_look(beam);
        renderer =
            std::make_unique<bz::render::Renderer>(settings, 1280, 720, bz::gl::TimingMethod::off);
        const std::size_t before = every_image_bytes(1280, 720, settings);
        for (Style style : bz::scene::all_styles()) {
            draw(style);
            const ResourceSet held = renderer->allocated_resources();
            const auto& def = bz::render::style_def(style);
            SCOPED_TRACE(std::string(bz::scene::style_name(style)) + " / " + beam);
            const ResourceSet needed =
                bz::render::resources_of(bz::render::frame_passes(def, renderer->settings()));
            EXPECT_TRUE(held.contains(needed));
            if (def.fill == bz::render::FillPass::none) {
                EXPECT_FALSE(held.has(Resource::canvas));
                EXPECT_FALSE(held.has(Resource::shrunk_depth));
                EXPECT_FALSE(held.has(Resource::halo));
            } else {
                EXPECT_FALSE(held.has(Resource::bloom_chain));
                EXPECT_FALSE(held.has(Resource::bloom_out));
            }
            const std::size_t bytes = renderer->allocated_bytes();
            EXPECT_LT(bytes, before);
            std::printf("targets 1280x720 %-11s %-7s: %6.2f MiB (every image: %6.2f MiB)\n",
                        std::string(bz::scene::style_name(style)).c_str(), beam.c_str(),
                        static_cast<double>(bytes) / 1048576.0,
                        static_cast<double>(before) / 1048576.0);
        }
    }
}

TEST_F(FrameStateTest, TheHistoryIsForgottenByItsRules) {
    settings.beam = bz::render::beam_look("mame");
    ASSERT_NE(settings.beam.phosphor, bz::render::PhosphorDecay::off);
    renderer = std::make_unique<bz::render::Renderer>(settings, kWidth, kHeight,
                                                      bz::gl::TimingMethod::off);
    const ResourceSet kept{Resource::phosphor, Resource::picture_lit, Resource::glow,
                           Resource::picture};
    draw(Style::vector);
    EXPECT_EQ(renderer->history_held(), kept);
    // A cut (camera jump, level reload) forgets it; the frame it cuts then keeps its own.
    frame.cut = true;
    draw(Style::vector);
    frame.cut = false;
    EXPECT_EQ(renderer->history_last_cut(), bz::render::HistoryCut::camera_cut);
    EXPECT_EQ(renderer->history_held(), kept);
    // A filled style writes no beam history: nothing held after its frame.
    draw(Style::toon);
    EXPECT_EQ(renderer->history_last_cut(), bz::render::HistoryCut::style_change);
    EXPECT_TRUE(renderer->history_held().empty());
    // Back to a beam style: its first frame has no past, and its images are made again.
    draw(Style::vector);
    EXPECT_EQ(renderer->history_held(), kept);
    EXPECT_FALSE(renderer->allocated_resources().has(Resource::canvas));
    // Resize: new targets, nothing kept.
    renderer->resize(kWidth / 2, kHeight / 2);
    EXPECT_TRUE(renderer->history_held().empty());
    // keep_history off (--edit): every frame forgets, and keeps nothing a later frame reads.
    settings.keep_history = false;
    renderer->set_settings(settings);
    draw(Style::vector);
    draw(Style::vector);
    EXPECT_EQ(renderer->history_last_cut(), bz::render::HistoryCut::no_history);
    settings.keep_history = true;
    renderer->set_settings(settings);
    renderer->resize(kWidth / 3, kHeight / 3);
    EXPECT_EQ(renderer->history_last_cut(), bz::render::HistoryCut::resize);
    EXPECT_TRUE(renderer->allocated_resources().empty());
    draw(Style::vector);
    EXPECT_EQ(renderer->history_held(), kept);
}

// A cut frame is the picture a fresh renderer draws: no trail of the frames before it. The
// same flight without the cut trails, so the comparison can fail.
TEST_F(FrameStateTest, ACutFrameHasNoTrails) {
    settings.beam = bz::render::beam_look("mame");
    settings.beam.refresh_hz = 0.0f;  // every frame drawn
    const auto flight = [&](bool cut) {
        renderer = std::make_unique<bz::render::Renderer>(settings, kWidth, kHeight,
                                                          bz::gl::TimingMethod::off);
        frame.time_s = 0.0;
        frame.camera.eye = {1.5, 1.2, 2.5};
        for (int i = 0; i < 4; ++i) {
            frame.camera.eye.x += 0.3;
            draw(Style::vector);
        }
        frame.camera.eye = {-1.5, 1.2, 2.5};
        frame.cut = cut;
        draw(Style::vector);
        frame.cut = false;
        return renderer->read_color();
    };
    const std::vector<std::uint8_t> cut = flight(true);
    const std::vector<std::uint8_t> trailing = flight(false);
    bz::render::Renderer fresh(settings, kWidth, kHeight, bz::gl::TimingMethod::off);
    fresh.render(frame, meshes, bz::render::Renderer::kOffscreen);
    EXPECT_EQ(cut, fresh.read_color());
    EXPECT_NE(trailing, fresh.read_color()) << "the look keeps no past: the test shows nothing";
}

}  // namespace
