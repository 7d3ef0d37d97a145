// Touching and coplanar geometry: a line on a face that lies against the back of another
// surface is hidden however thin that surface is; a line seen through a gap is drawn. The
// scenes are a thin slab with battens under it (rafters under a roof, studs behind a wall),
// seen from above, in every preset and both depth formats, checked against the exact CPU
// reference and against the slab drawn alone.
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/reference/mask_score.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

namespace {

using bz::render::DepthFormat;
namespace geo = bz::geo;

constexpr double kThickness = 0.005;  // the slab: 5e-4 of the view depth, under a pixel thick
constexpr double kHalf = 4.0;         // slab half size in x and z
constexpr double kSlotHalf = 0.1;     // half width of the slot (about 4 px wide on screen)

struct Case {
    const char* preset;
    DepthFormat depth;
};

std::string case_name(const Case& c) {
    return std::string(c.preset) + (c.depth == DepthFormat::reversed_f32 ? "_f32" : "_d24");
}

class TouchingGeometryTest : public bz::test::RenderTest,
                             public ::testing::WithParamInterface<Case> {
  protected:
    void SetUp() override {
        settings = bz::render::preset(GetParam().preset);
        settings.depth = GetParam().depth;
        settings.lod = false;  // the reference is full detail
        RenderTest::SetUp();
    }

    void reset() {
        meshes = {};
        frame.items.clear();
        renderer = std::make_unique<bz::render::Renderer>(settings, kWidth, kHeight,
                                                          bz::gl::TimingMethod::off);
        // From above and to the side, about 10 units from the slab's centre.
        frame.camera.eye = {3.0, 8.0, 5.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 45.0;
        frame.camera.near = 0.1;
        frame.camera.far = 100.0;
    }

    // The slab: its underside in y = 0, top at kThickness; with a slot, two halves with a gap
    // of 2 kSlotHalf around x = 0, running along z.
    void add_slab(bool slot) {
        const double t = kThickness;
        const glm::dmat4 up = glm::translate(glm::dmat4(1.0), {0.0, t / 2, 0.0});
        if (!slot) {
            add_item(add_mesh("slab", geo::box(glm::vec3(kHalf, t / 2, kHalf))), up);
            return;
        }
        const double half_w = (kHalf - kSlotHalf) / 2;
        const auto part = add_mesh("slab-half", geo::box(glm::vec3(half_w, t / 2, kHalf)));
        add_item(part, glm::translate(up, {-(kSlotHalf + half_w), 0.0, 0.0}));
        add_item(part, glm::translate(up, {kSlotHalf + half_w, 0.0, 0.0}));
    }

    // Five battens along x (across the slot), 0.2 x 0.2, their tops `gap` below y = 0.
    void add_battens(double gap) {
        const auto batten = add_mesh("batten", geo::box(glm::vec3(3.5f, 0.1f, 0.1f)));
        for (int i = -2; i <= 2; ++i) {
            add_item(batten, glm::translate(glm::dmat4(1.0), {0.0, -0.1 - gap, 1.2 * i}));
        }
    }

    std::vector<std::uint8_t> reference() {
        return bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
    }

    // Lit pixels of `m` with no lit pixel of `base` within 1 px: lines `base` does not have.
    static int extra_pixels(const bz::test::Mask& m, const std::vector<std::uint8_t>& base) {
        int n = 0;
        for (int y = 0; y < m.height; ++y) {
            for (int x = 0; x < m.width; ++x) {
                if (!m.lit(x, y)) continue;
                bool near_base = false;
                for (int dy = -1; dy <= 1 && !near_base; ++dy) {
                    for (int dx = -1; dx <= 1 && !near_base; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        near_base = nx >= 0 && ny >= 0 && nx < m.width && ny < m.height &&
                                    base[static_cast<std::size_t>(ny * m.width + nx)] != 0;
                    }
                }
                n += near_base ? 0 : 1;
            }
        }
        return n;
    }

    // The slab alone: what the hidden-battens scenes must look like.
    bz::test::Mask slab_alone(bool slot) {
        reset();
        add_slab(slot);
        return mask();
    }
};

TEST_P(TouchingGeometryTest, BattensTouchingTheUndersideAreHidden) {
    const bz::test::Mask alone = slab_alone(false);
    reset();
    add_slab(false);
    add_battens(0.0);
    const std::string name = "touching_" + case_name(GetParam());
    const bz::test::Mask m = mask(name);
    const std::vector<std::uint8_t> ref = reference();
    // The reference agrees that nothing of the battens shows.
    EXPECT_EQ(extra_pixels(bz::test::Mask{kWidth, kHeight, ref}, alone.pixels), 0);
    EXPECT_EQ(extra_pixels(m, alone.pixels), 0) << "batten lines leak through the slab";
    const geo::MaskScore s = geo::score_masks(m.pixels, ref, kWidth, kHeight, 1);
    EXPECT_GE(s.f1, 0.99) << "P " << s.precision << " R " << s.recall;
}

TEST_P(TouchingGeometryTest, BattensOnePercentOfTheDepthBelowAreHidden) {
    const bz::test::Mask alone = slab_alone(false);
    reset();
    add_slab(false);
    add_battens(0.01 * glm::length(frame.camera.eye - frame.camera.target));
    const bz::test::Mask m = mask("below_" + case_name(GetParam()));
    EXPECT_EQ(extra_pixels(m, alone.pixels), 0) << "batten lines leak through the slab";
}

TEST_P(TouchingGeometryTest, BattensSeenThroughASlotAreDrawn) {
    const bz::test::Mask alone = slab_alone(true);
    reset();
    add_slab(true);
    add_battens(0.0);
    const bz::test::Mask m = mask("slot_" + case_name(GetParam()));
    const std::vector<std::uint8_t> ref = reference();
    const int ref_extra = extra_pixels(bz::test::Mask{kWidth, kHeight, ref}, alone.pixels);
    const int gpu_extra = extra_pixels(m, alone.pixels);
    std::printf("[touching] %-14s slot: batten pixels %d (reference %d)\n",
                case_name(GetParam()).c_str(), gpu_extra, ref_extra);
    ASSERT_GT(ref_extra, 20) << "the slot shows too little of the battens to test";
    // The battens' lines in the slot are drawn: most of the reference's, and no others.
    EXPECT_GE(gpu_extra, ref_extra * 7 / 10);
    const geo::MaskScore s = geo::score_masks(m.pixels, ref, kWidth, kHeight, 1);
    EXPECT_GE(s.f1, 0.97) << "P " << s.precision << " R " << s.recall;
}

INSTANTIATE_TEST_SUITE_P(Presets, TouchingGeometryTest,
                         ::testing::Values(Case{"fast", DepthFormat::reversed_f32},
                                           Case{"balanced", DepthFormat::reversed_f32},
                                           Case{"high", DepthFormat::reversed_f32},
                                           Case{"balanced", DepthFormat::conventional_d24},
                                           Case{"high", DepthFormat::conventional_d24}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                             return case_name(p.param);
                         });

}  // namespace
