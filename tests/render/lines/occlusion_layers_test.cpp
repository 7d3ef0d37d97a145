// Hidden lines by occlusion level on the GPU (pass_occlusion_layers.cpp,
// shaders/lines/occlusion_level.glsl) against the exact reference's levels
// (geo::reference_segments with hidden_levels): per level, the pixels the GPU marks with that
// level against the pixels the reference's segments of that level cross; the technical style's
// dashes anchored to their edges in two camera poses; and the styles that draw no hidden lines
// untouched by the layers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "core/image_io.h"
#include "geometry/generated/primitives.h"
#include "geometry/import/import.h"
#include "geometry/reference/reference.h"
#include "geometry/reference/reference_raster.h"
#include "render/camera/camera_framing.h"
#include "render/frame_passes.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"
#include "render/styles/style_def.h"
#include "scene/style_table.h"
#include "support/tree_paths.h"

namespace {

using bz::scene::Style;
using bz::test::Mask;

// The mask value of occlusion level L (RenderSettings::mask_occlusion_levels).
constexpr std::uint8_t level_code(int level) {
    return static_cast<std::uint8_t>(255 - 64 * level);
}

class OcclusionLayersTest : public bz::test::RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        compare_line_methods = false;  // the technical strokes read the edge buffer either way
        frame.style = Style::technical;
    }

    // A bar behind a cube behind a smaller cube (the reference's own scene), seen a little
    // from the side and above so that no face is exactly edge-on: the bar's edges run at
    // levels 0 to 3, the cubes' back edges at 1 and 2.
    void three_cubes(glm::dvec3 eye) {
        const auto bar = add_mesh("bar", bz::geo::box({3.0, 0.5, 1.0}));
        const auto big = add_mesh("big", bz::geo::box({1.0, 1.0, 1.0}));
        const auto small = add_mesh("small", bz::geo::box({0.3, 0.3, 0.3}));
        auto at = [](double z) { return glm::translate(glm::dmat4(1.0), {0.0, 0.0, z}); };
        add_item(bar, at(-4.0));
        add_item(big, at(0.0));
        add_item(small, at(4.0));
        frame.camera.eye = eye;
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 50.0;
        frame.camera.near = 0.1;
        frame.camera.far = 100.0;
    }

    std::vector<bz::geo::VisibleSegment> reference_levels() const {
        bz::render::ReferenceFrameOptions o;
        o.sampling.hidden_levels = bz::geo::kMaxOcclusionLevel;
        return bz::render::reference_frame_segments(frame, meshes, kWidth, kHeight, o);
    }

    // The pixels whose lowest level among the reference's segments crossing them is `level`:
    // the GPU's mask keeps the lowest level at each pixel (MAX blending of the codes).
    static Mask reference_level(const std::vector<bz::geo::VisibleSegment>& segments, int level) {
        Mask m{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight, 0)};
        std::vector<std::uint8_t> lower(m.pixels.size(), 0);
        for (const auto& s : segments) {
            if (s.level == level)
                bz::geo::detail::mark_segment(m.pixels, kWidth, kHeight, s.a, s.b);
            else if (s.level < level)
                bz::geo::detail::mark_segment(lower, kWidth, kHeight, s.a, s.b);
        }
        for (std::size_t i = 0; i < m.pixels.size(); ++i)
            if (lower[i]) m.pixels[i] = 0;
        return m;
    }

    static Mask gpu_level(const Mask& levels, int level) {
        Mask m{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight, 0)};
        for (std::size_t i = 0; i < m.pixels.size(); ++i)
            m.pixels[i] = levels.pixels[i] == level_code(level) ? 255 : 0;
        return m;
    }

    Mask level_mask(const std::string& name) {
        // The reference's levels in the same code, for looking at (build/test-out/).
        Mask ref{kWidth, kHeight, std::vector<std::uint8_t>(kWidth * kHeight, 0)};
        const auto segments = reference_levels();
        for (int level = 0; level <= bz::geo::kMaxOcclusionLevel; ++level) {
            const Mask m = reference_level(segments, level);
            for (std::size_t i = 0; i < m.pixels.size(); ++i)
                if (m.pixels[i]) ref.pixels[i] = level_code(level);
        }
        bz::write_png(bz::test::binary_dir() / "test-out" / (name + "_reference.png"),
                      bz::Image{kWidth, kHeight, 1, ref.pixels});
        settings.mask_occlusion_levels = true;
        Mask m = mask(name);
        settings.mask_occlusion_levels = false;
        return m;
    }

    // F1 at 1 px of the GPU's level-`level` pixels against the reference's; -1 when neither
    // has any.
    static double level_f1(const Mask& gpu, const std::vector<bz::geo::VisibleSegment>& ref,
                           int level, int* ref_pixels = nullptr) {
        const Mask r = reference_level(ref, level);
        const Mask g = gpu_level(gpu, level);
        if (ref_pixels) *ref_pixels = r.count();
        if (r.count() == 0 && g.count() == 0) return -1.0;
        const bz::test::MaskScore s = bz::test::score_masks(g, r, 1);
        std::printf("level %d: %d GPU pixels, %d reference pixels, precision %.4f recall %.4f\n",
                    level, g.count(), r.count(), s.precision, s.recall);
        return s.precision + s.recall > 0.0
                   ? 2.0 * s.precision * s.recall / (s.precision + s.recall)
                   : 0.0;
    }

    // Ink darkness (0 paper .. 1 black) of the darkest pixel within r px of window point p.
    static double ink_near(const std::vector<std::uint8_t>& rgba, glm::dvec2 p, int r = 1) {
        double darkest = 0.0;
        const int cx = static_cast<int>(std::floor(p.x)), cy = static_cast<int>(std::floor(p.y));
        for (int y = cy - r; y <= cy + r; ++y)
            for (int x = cx - r; x <= cx + r; ++x) {
                if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) continue;
                const std::size_t i = (static_cast<std::size_t>(kHeight - 1 - y) * kWidth + x) * 4;
                darkest = std::max(darkest, 1.0 - rgba[i] / 255.0);
            }
        return darkest;
    }

    // Along every long hidden segment of the reference, whether the technical frame has ink at
    // the middle of each dash and paper at the middle of each gap, with the pattern measured
    // from the edge's first end (VisibleSegment::edge_offset_px): the share of such points that
    // agree. Points within 3 px of any other line are left out.
    double dash_agreement(const std::vector<std::uint8_t>& rgba,
                          const std::vector<bz::geo::VisibleSegment>& ref, int* points) const {
        const auto& h = bz::render::style_def(Style::technical).hidden;
        const double period = h.dash_px + h.gap_px;
        int agree = 0, n = 0;
        for (std::size_t k = 0; k < ref.size(); ++k) {
            const auto& s = ref[k];
            const double len = glm::length(s.b - s.a);
            if (s.level == 0 || len < 2.0 * period) continue;
            const glm::dvec2 dir = (s.b - s.a) / len;
            for (double d = 3.0; d < len - 3.0; d += 0.5) {
                const double phase = std::fmod(s.edge_offset_px + d, period);
                const bool dash_middle = std::abs(phase - 0.5 * h.dash_px) <= 0.5 * h.dash_px - 1.5;
                const bool gap_middle =
                    std::abs(phase - h.dash_px - 0.5 * h.gap_px) <= 0.5 * h.gap_px - 1.5;
                if (!dash_middle && !gap_middle) continue;
                const glm::dvec2 p = s.a + dir * d;
                bool alone = true;
                for (std::size_t j = 0; j < ref.size() && alone; ++j) {
                    if (j == k) continue;
                    const glm::dvec2 ab = ref[j].b - ref[j].a;
                    const double t = glm::clamp(
                        glm::dot(p - ref[j].a, ab) / std::max(glm::dot(ab, ab), 1e-12), 0.0, 1.0);
                    alone = glm::length(ref[j].a + ab * t - p) > 3.0;
                }
                if (!alone) continue;
                ++n;
                const double ink = ink_near(rgba, p);
                // A dash has ink within a pixel of its middle; a gap no more than the paper's
                // shading (0.03) in the pixel at its middle (a 3x3 block would reach the
                // dashes' antialiased ends).
                agree += dash_middle ? ink > 0.25 : ink_near(rgba, p, 0) < 0.1;
            }
        }
        *points = n;
        return n > 0 ? static_cast<double>(agree) / n : 0.0;
    }
};

TEST_F(OcclusionLayersTest, ThreeCubesLevelsMatchTheExactReference) {
    three_cubes({0.6, 0.4, 10.0});
    const auto ref = reference_levels();
    const Mask gpu = level_mask("occlusion_levels_three_cubes");
    for (int level = 0; level <= bz::geo::kMaxOcclusionLevel; ++level) {
        int ref_pixels = 0;
        const double f1 = level_f1(gpu, ref, level, &ref_pixels);
        EXPECT_GT(ref_pixels, 20) << "the scene has lines of level " << level;
        EXPECT_GE(f1, 0.99) << "level " << level << " (" << ref_pixels << " reference pixels)";
    }
}

TEST_F(OcclusionLayersTest, BothDepthFormatsCountTheSameLevels) {
    three_cubes({-0.5, -0.3, 9.0});
    const auto ref = reference_levels();
    settings.depth = bz::render::DepthFormat::conventional_d24;
    const Mask gpu = level_mask("occlusion_levels_three_cubes_d24");
    for (int level = 0; level <= bz::geo::kMaxOcclusionLevel; ++level)
        EXPECT_GE(level_f1(gpu, ref, level), 0.99) << "level " << level;
}

TEST_F(OcclusionLayersTest, RealModelLevelsMatchTheExactReference) {
    show_model("/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf");
    const auto ref = reference_levels();
    const Mask gpu = level_mask("occlusion_levels_milk_truck");
    for (int level = 0; level <= bz::geo::kMaxOcclusionLevel; ++level) {
        int ref_pixels = 0;
        const double f1 = level_f1(gpu, ref, level, &ref_pixels);
        if (ref_pixels < 50) continue;  // too few to score
        EXPECT_GE(f1, 0.95) << "level " << level << " (" << ref_pixels << " reference pixels)";
    }
}

TEST_F(OcclusionLayersTest, DashesStayOnTheirEdgesAsTheCameraMoves) {
    for (const glm::dvec3 eye : {glm::dvec3(1.6, 1.1, 10.0), glm::dvec3(1.75, 1.0, 9.8)}) {
        frame.items.clear();
        three_cubes(eye);
        const auto ref = reference_levels();
        renderer->set_settings(settings);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        const std::vector<std::uint8_t> rgba = renderer->read_color();
        save_color("occlusion_levels_technical_" + std::to_string(eye.x));
        int points = 0;
        const double agree = dash_agreement(rgba, ref, &points);
        EXPECT_GT(points, 100);
        EXPECT_GE(agree, 0.95) << points << " dash and gap middles";
    }
}

// vector-xray: every line drawn, each level dimmer. The brightest pixel near the middle of
// each long, lone reference segment, averaged per level: level 0 brightest, then 1, then 2.
TEST_F(OcclusionLayersTest, XrayDimsHiddenLinesByLevelInBothLineMethods) {
    three_cubes({1.6, 1.1, 10.0});
    const auto ref = reference_levels();
    frame.style = Style::vector_xray;
    for (const auto method : bz::render::feature_line_methods()) {
        settings.method = method;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        const std::vector<std::uint8_t> rgba = renderer->read_color();
        save_color("occlusion_levels_xray_" + std::string(bz::render::line_method_name(method)));
        double sum[3] = {0.0, 0.0, 0.0};
        int n[3] = {0, 0, 0};
        for (const auto& s : ref) {
            if (s.level > 2 || glm::length(s.b - s.a) < 8.0) continue;
            const glm::dvec2 mid = 0.5 * (s.a + s.b);
            bool alone = true;
            for (const auto& o : ref) {
                if (&o == &s) continue;
                const glm::dvec2 ab = o.b - o.a;
                const double t = glm::clamp(
                    glm::dot(mid - o.a, ab) / std::max(glm::dot(ab, ab), 1e-12), 0.0, 1.0);
                alone = alone && glm::length(o.a + ab * t - mid) > 4.0;
            }
            if (!alone) continue;
            double brightest = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = static_cast<int>(mid.x) + dx, y = static_cast<int>(mid.y) + dy;
                    if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) continue;
                    const std::size_t i =
                        (static_cast<std::size_t>(kHeight - 1 - y) * kWidth + x) * 4;
                    brightest = std::max(brightest, rgba[i + 1] / 255.0);  // green
                }
            sum[s.level] += brightest;
            ++n[s.level];
        }
        const std::string m(bz::render::line_method_name(method));
        ASSERT_GT(n[0], 0) << m;
        ASSERT_GT(n[1], 0) << m;
        ASSERT_GT(n[2], 0) << m;
        const double b0 = sum[0] / n[0], b1 = sum[1] / n[1], b2 = sum[2] / n[2];
        EXPECT_GT(b0, b1 * 1.1) << m << ": level 0 " << b0 << ", level 1 " << b1;
        EXPECT_GT(b1, b2 * 1.1) << m << ": level 1 " << b1 << ", level 2 " << b2;
    }
}

// Only the styles that draw hidden lines by level peel the layers: every other style's frame
// runs and allocates what it did before.
TEST(OcclusionLayersPasses, OnlyTechnicalAndXrayPeelLayers) {
    for (int i = 0; i <= static_cast<int>(bz::scene::kLastStyle); ++i) {
        const auto style = static_cast<Style>(i);
        const bool wants = style == Style::technical || style == Style::vector_xray;
        for (const auto method : bz::render::feature_line_methods()) {
            bz::render::RenderSettings settings = bz::render::preset("balanced");
            settings.method = method;
            const auto list = bz::render::frame_passes(bz::render::style_def(style), settings);
            EXPECT_EQ(bz::render::resources_of(list).has(bz::render::Resource::peel_layers), wants)
                << bz::scene::style_entry(style).name;
        }
    }
}

}  // namespace
