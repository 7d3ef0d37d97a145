// The vector beam (render::BeamSettings): phosphor decay in elapsed time, additive against max
// blending, beam dwell, overdrive defocus, flicker and MAME's lengthened ends. HUD lines are
// drawn through the same beam maths as scene lines (shaders/beam/beam_width.glsl) and need no
// meshes or camera, so most tests draw HUD lines and read the HDR picture that bloom and composite
// see; the lengthening tests also draw scene lines, in both line methods.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "geometry/mesh.h"
#include "render/render_fixture.h"

using bz::test::RenderTest;

namespace {

constexpr int kBeamW = 320;
constexpr int kBeamH = 240;

// HUD units (origin at the centre, y up, 1 = half the height) of pixel centre (x, y), row 0 at
// the top.
glm::vec2 hud_at(float x, float y) {
    return {(x + 0.5f - kBeamW * 0.5f) / (kBeamH * 0.5f),
            (kBeamH * 0.5f - y - 0.5f) / (kBeamH * 0.5f)};
}

bz::scene::HudLine line(glm::vec2 a, glm::vec2 b, float intensity) {
    return {a, b, glm::vec3(0.0f, 1.0f, 0.0f), intensity};
}

// A beam with every effect off: constant half-width 3 px, GL_MAX, no bloom. The HUD lines
// this file draws stand for beam lines: they keep the scene's beam (RenderSettings::hud_glow).
bz::render::RenderSettings plain() {
    bz::render::RenderSettings s = bz::render::preset("balanced");
    s.line_half_width_px = 3.0f;
    s.bloom_strength = 0.0f;
    s.hud_glow = true;
    return s;
}

// A horizontal HUD line through row 120 from x = 60 to x = 260.
bz::scene::FrameList lit_frame(double time_s, float intensity = 1.0f) {
    bz::scene::FrameList f;
    f.time_s = time_s;
    f.hud.push_back(line(hud_at(60, 120), hud_at(260, 120), intensity));
    return f;
}

bz::scene::FrameList dark_frame(double time_s) {
    bz::scene::FrameList f;
    f.time_s = time_s;
    return f;
}

class BeamTest : public RenderTest {
  protected:
    // Renders the frame and returns the green channel of the picture (row 0 at the top).
    std::vector<float> green(const bz::scene::FrameList& f) {
        renderer->render(f, meshes, bz::render::Renderer::kOffscreen);
        const std::vector<float> rgba = renderer->read_picture_hdr();
        std::vector<float> g(static_cast<std::size_t>(kBeamW) * kBeamH);
        for (std::size_t i = 0; i < g.size(); ++i) g[i] = rgba[i * 4 + 1];
        return g;
    }
    static float at(const std::vector<float>& img, int x, int y) {
        return img[static_cast<std::size_t>(y) * kBeamW + x];
    }
    static float peak(const std::vector<float>& img) {
        return *std::max_element(img.begin(), img.end());
    }
    float centre(const bz::scene::FrameList& f) { return at(green(f), 160, 120); }
    void use(const bz::render::RenderSettings& s) {
        settings = s;
        renderer->set_settings(s);
    }
    // Lights the line at t = 0, then shows empty frames at `fps` until `until_s`; returns the
    // brightness left on the line's centre relative to its first frame.
    double phosphor_left(double fps, double until_s) {
        const float first = centre(lit_frame(0.0));
        const int frames = static_cast<int>(std::lround(until_s * fps));
        float last = first;
        for (int i = 1; i <= frames; ++i) last = centre(dark_frame(i / fps));
        return static_cast<double>(last) / first;
    }
};

}  // namespace

TEST_F(BeamTest, PhosphorDecayFollowsExpOfElapsedTimeAtAnyFrameRate) {
    auto s = plain();
    s.beam.phosphor = bz::render::PhosphorDecay::exponential;
    s.beam.persistence_ms = 100.0f;
    const double until = 1.0 / 6.0;  // 5 frames at 30 fps, 24 at 144 fps
    const double expected = std::exp(-until / 0.1);
    for (const double fps : {30.0, 144.0}) {
        use(s);  // new targets: the phosphor starts black
        const double left = phosphor_left(fps, until);
        EXPECT_NEAR(left / expected, 1.0, 0.01)
            << fps << " fps: " << left << " left, expected " << expected;
    }
}

TEST_F(BeamTest, PowerLawPhosphorIsHalfAtItsPersistenceAtAnyFrameRate) {
    auto s = plain();
    s.beam.phosphor = bz::render::PhosphorDecay::power_law;
    s.beam.persistence_ms = 50.0f;
    s.beam.power_law_exponent = 2.0f;
    for (const double fps : {30.0, 60.0}) {  // 50 ms: 1.5 frames at 30 fps -> use 100 ms too
        use(s);
        const double left = phosphor_left(fps, 0.1);
        // (1 + t/t0)^-p with t0 = 50 ms / (2^(1/2) - 1): at 100 ms
        const double t0 = 0.05 / (std::sqrt(2.0) - 1.0);
        const double expected = std::pow(1.0 + 0.1 / t0, -2.0);
        EXPECT_NEAR(left / expected, 1.0, 0.01) << fps << " fps";
    }
}

TEST_F(BeamTest, WithoutPhosphorAnEmptyFrameIsBlack) {
    use(plain());
    EXPECT_GT(centre(lit_frame(0.0)), 0.5f);
    EXPECT_EQ(centre(dark_frame(1.0 / 60.0)), 0.0f);
}

TEST_F(BeamTest, AdditiveBlendingAddsAtACrossingMaxDoesNot) {
    bz::scene::FrameList f;
    f.hud.push_back(line(hud_at(60, 120), hud_at(260, 120), 1.0f));  // horizontal, row 120
    f.hud.push_back(line(hud_at(160, 40), hud_at(160, 200), 1.0f));  // vertical, column 160
    for (const auto blend : {bz::render::BeamBlend::max, bz::render::BeamBlend::additive}) {
        auto s = plain();
        s.beam.blend = blend;
        use(s);
        const auto img = green(f);
        const float single = at(img, 100, 120);  // on the horizontal line only
        const float crossing = at(img, 160, 120);
        ASSERT_GT(single, 0.5f);
        if (blend == bz::render::BeamBlend::max) {
            EXPECT_NEAR(crossing, single, 1e-3f) << "GL_MAX: a crossing is as bright as one line";
        } else {
            EXPECT_NEAR(crossing, 2.0f * single, 2e-3f * single)
                << "additive: a crossing is two lines";
        }
    }
}

TEST_F(BeamTest, DwellRaisesADotsPeakAboveALongVectors) {
    bz::scene::FrameList dot, vec;
    dot.hud.push_back(line(hud_at(160, 120), hud_at(160, 120), 1.0f));
    vec.hud.push_back(line(hud_at(40, 120), hud_at(280, 120), 1.0f));
    auto s = plain();
    use(s);
    const float dot_plain = peak(green(dot)), vec_plain = peak(green(vec));
    EXPECT_NEAR(dot_plain, vec_plain, 1e-3f) << "without dwell a dot is as bright as a line";
    s.beam.dwell_px = 20.0f * 1080.0f / kBeamH;  // 20 px here
    s.beam.dwell_max = 3.0f;
    use(s);
    const float dot_dwell = peak(green(dot)), vec_dwell = peak(green(vec));
    EXPECT_NEAR(dot_dwell, 3.0f * dot_plain, 0.01f * dot_plain) << "a dot gets the full dwell gain";
    // The 240 px vector: (240 + 20) / 240 of its plain brightness.
    EXPECT_NEAR(vec_dwell, vec_plain * 260.0f / 240.0f, 0.01f * vec_plain);
    EXPECT_GT(dot_dwell, 2.5f * vec_dwell);
}

TEST_F(BeamTest, IntensityWidensTheBeamAndOverdriveKeepsWideningWithoutClipping) {
    auto s = plain();
    s.beam.intensity_width = true;
    s.beam.width_min_px = 2.0f * 1080.0f / kBeamH;  // half-widths 1 .. 4 px on this target
    s.beam.width_max_px = 8.0f * 1080.0f / kBeamH;
    s.beam.intensity_weight = 0.75f;
    s.beam.nominal = 0.75f;
    s.beam.defocus = 1.5f;
    use(s);
    int last_width = 0;
    float last_peak = 0.0f;
    for (const float intensity : {0.25f, 0.5f, 1.0f, 1.33f, 2.0f, 3.0f, 4.0f, 6.0f}) {
        const auto img = green(lit_frame(0.0, intensity));
        int width = 0;  // lit rows in column 160
        for (int y = 0; y < kBeamH; ++y) width += at(img, 160, y) > 0.0f ? 1 : 0;
        EXPECT_GE(width, last_width) << "intensity " << intensity;
        const float p = at(img, 160, 120);
        EXPECT_LT(p, 1.6f) << "intensity " << intensity
                           << ": an overdriven beam spreads instead of clipping";
        last_width = width;
        last_peak = p;
    }
    EXPECT_GE(last_width, 20) << "intensity 6 is far past full: a wide, defocused spot";
    EXPECT_GT(last_peak, 0.5f);
}

TEST_F(BeamTest, FlickerRepeatsForTheSameSeedAndChangesWithIt) {
    auto s = plain();
    s.beam.flicker = 0.5f;
    use(s);
    bz::scene::FrameList f;
    for (int i = 0; i < 16; ++i) {
        const float y = 20.0f + 12.0f * static_cast<float>(i);
        f.hud.push_back(line(hud_at(60, y), hud_at(260, y), 1.0f));
    }
    f.seed = 7;
    const auto a = green(f), b = green(f);
    EXPECT_EQ(a, b);
    f.seed = 8;
    const auto c = green(f);
    EXPECT_NE(a, c);
    // Flicker only takes intensity away, by at most the flicker share.
    use(plain());
    const float full = peak(green(f));
    EXPECT_LE(peak(c), full + 1e-4f);
    for (int i = 0; i < 16; ++i) EXPECT_GE(at(c, 160, 20 + 12 * i), 0.5f * full - 1e-3f);
}

namespace {

// The camera of the lengthening tests: looking down -z at the origin, so that at z = 0 one
// world unit is one pixel and world (0, 0) is the picture's centre (window x 160, y 120).
constexpr double kEyeDistance = 120.0 / 0.57735026918962576;  // kBeamH / 2 / tan(30 deg)

// World x at depth z of window x `px` (pixels from the left).
double world_x(double px, double z) {
    return (px - kBeamW * 0.5) * (kEyeDistance - z) / kEyeDistance;
}

// A flat rectangle facing the camera, window x `x0`..`x1`, window rows (from the top) centred
// on `row` and `rows` tall, at depth z. Its four sides are boundary edges, so a strip 0.2 px
// tall draws as one horizontal line.
bz::geo::TriMesh rectangle(double x0, double x1, double row, double rows, double z) {
    const double s = (kEyeDistance - z) / kEyeDistance;
    const float l = static_cast<float>(world_x(x0, z)), r = static_cast<float>(world_x(x1, z));
    const float y = static_cast<float>((kBeamH * 0.5 - row - 0.5) * s),
                h = static_cast<float>(rows * 0.5 * s);
    const float zf = static_cast<float>(z);
    return {
        {{l, y - h, zf}, {r, y - h, zf}, {r, y + h, zf}, {l, y + h, zf}}, {0, 1, 2, 0, 2, 3}, {}};
}

// Where along row `y` the brightness first and last reaches half of the row's peak, with
// linear interpolation between pixel centres (window x, pixels from the left).
std::pair<double, double> half_peak_extent(const std::vector<float>& img, int y) {
    const auto v = [&](int x) {
        return static_cast<double>(img[static_cast<std::size_t>(y) * kBeamW + x]);
    };
    double top = 0.0;
    for (int x = 0; x < kBeamW; ++x) top = std::max(top, v(x));
    const double half = 0.5 * top;
    double first = -1.0, last = -1.0;
    for (int x = 1; x < kBeamW; ++x) {
        const double a = v(x - 1), b = v(x);
        if (a < half && b >= half && first < 0.0) first = x - 0.5 + (half - a) / (b - a);
        if (a >= half && b < half) last = x - 0.5 + (a - half) / (a - b);
    }
    return {first, last};
}

bz::scene::Camera facing_camera() {
    bz::scene::Camera c;
    c.eye = {0.0, 0.0, kEyeDistance};
    c.target = {0.0, 0.0, 0.0};
    c.fov_y_deg = 60.0;
    return c;
}

// The row holding the most light (a strip's line; its short ends, lengthened, reach a few rows
// up and down as bright, but hold far less light in all).
int brightest_row(const std::vector<float>& img) {
    int best = 0;
    double best_sum = -1.0;
    for (int y = 0; y < kBeamH; ++y) {
        double sum = 0.0;
        for (int x = 0; x < kBeamW; ++x)
            sum += static_cast<double>(img[static_cast<std::size_t>(y) * kBeamW + x]);
        if (sum > best_sum) {
            best_sum = sum;
            best = y;
        }
    }
    return best;
}

}  // namespace

// MAME (src/emu/video/vector.cpp) moves both ends of every vector out by 3/8 of the beam's
// width. With a constant half-width of 4 px (width 8) that is 3 px at each end.
TEST_F(BeamTest, HudLineEndsAreLengthenedByThreeEighthsOfTheWidth) {
    auto s = plain();
    s.line_half_width_px = 4.0f;
    use(s);
    const auto before = half_peak_extent(green(lit_frame(0.0)), 120);
    s.beam.end_lengthening = 0.375f;
    use(s);
    const auto after = half_peak_extent(green(lit_frame(0.0)), 120);
    EXPECT_NEAR(before.first - after.first, 3.0, 0.2) << "left end";
    EXPECT_NEAR(after.second - before.second, 3.0, 0.2) << "right end";
    // The middle of the line is untouched.
    EXPECT_NEAR(after.second - after.first, before.second - before.first + 6.0, 0.3);
}

TEST_F(BeamTest, SceneLineEndsAreLengthenedInBothMethodsAndTheMaskIsNot) {
    frame.camera = facing_camera();
    add_item(add_mesh("strip", rectangle(60.5, 260.5, 120.0, 0.2, 0.0)));
    for (const auto method : bz::render::feature_line_methods()) {
        SCOPED_TRACE(bz::render::line_method_name(method));
        auto s = plain();
        s.method = method;
        s.line_half_width_px = 4.0f;
        use(s);
        const auto img_before = green(frame);
        const int row = brightest_row(img_before);
        const auto before = half_peak_extent(img_before, row);
        const bz::test::Mask mask_before = mask("beam_strip");
        s.beam.end_lengthening = 0.375f;
        use(s);
        const auto after = half_peak_extent(green(frame), row);
        EXPECT_NEAR(before.first - after.first, 3.0, 0.25) << "left end";
        EXPECT_NEAR(after.second - before.second, 3.0, 0.25) << "right end";
        const bz::test::Mask mask_after = mask("beam_strip_lengthened");
        EXPECT_GT(mask_after.count(), 150);
        EXPECT_EQ(mask_after.pixels, mask_before.pixels)
            << "the accuracy mask ignores the beam's ends";
    }
}

// The strip's right end lies 1.5 px behind a red square in front of it: hidden. Lengthened,
// the end would reach past the square's right side; the end point decides, so it stays dark.
// (Deciding at the lengthened spine point instead would light a green stub there.)
TEST_F(BeamTest, ALengthenedEndShowsOnlyWhereItsEndPointIsVisible) {
    frame.camera = facing_camera();
    add_item(add_mesh("strip", rectangle(60.5, 200.0, 120.0, 0.2, 0.0)));
    add_item(add_mesh("square", rectangle(180.0, 201.5, 120.0, 40.0, 10.0)));
    frame.items.back().color = glm::vec3(1.0f, 0.0f, 0.0f);  // its own lines hold no green
    for (const auto method : bz::render::feature_line_methods()) {
        SCOPED_TRACE(bz::render::line_method_name(method));
        auto s = plain();
        s.method = method;
        s.line_half_width_px = 4.0f;
        s.beam.end_lengthening = 0.375f;
        use(s);
        const auto img = green(frame);
        const int row = brightest_row(img);
        EXPECT_GT(at(img, 150, row), 0.5f) << "the visible part of the strip";
        for (int x = 202; x < 212; ++x) EXPECT_EQ(at(img, x, row), 0.0f) << "x " << x;
        for (int x = 184; x < 200; ++x)
            EXPECT_EQ(at(img, x, row), 0.0f) << "behind the square, x " << x;
    }
}
