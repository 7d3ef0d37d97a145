// The sparse composite (pass_tiles.cpp, pass_composite.cpp) shades only the screen tiles where
// the picture or its glow is lit and clears the rest: the frame must be the one the dense,
// every-pixel composite draws, faint glow and screen edges included, in both beam looks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "render/render_fixture.h"

namespace {

constexpr int kSparseW = 320;
constexpr int kSparseH = 240;

glm::vec2 sparse_hud_at(float x, float y) {
    return {(x + 0.5f - kSparseW * 0.5f) / (kSparseH * 0.5f),
            (kSparseH * 0.5f - y - 0.5f) / (kSparseH * 0.5f)};
}

// Lines of every brightness, from full to barely above black, some along the screen's edges
// and corners (where tiles are cut off), a dot, and a crossing.
bz::scene::FrameList scattered_lines(double time_s, float shift) {
    bz::scene::FrameList f;
    f.time_s = time_s;
    const auto add = [&](glm::vec2 a, glm::vec2 b, glm::vec3 c, float i) {
        f.hud.push_back({sparse_hud_at(a.x + shift, a.y), sparse_hud_at(b.x + shift, b.y), c, i});
    };
    add({20, 30}, {150, 30}, {0.2f, 1.0f, 0.3f}, 1.0f);
    add({40, 200}, {40, 60}, {1.0f, 0.2f, 0.2f}, 0.6f);
    add({200, 100}, {300, 220}, {1.0f, 1.0f, 1.0f}, 0.02f);  // faint: only its glow's edge
    add({250, 20}, {250, 20}, {0.1f, 1.0f, 0.1f}, 0.5f);     // a dot
    add({0, 239}, {319, 239}, {0.1f, 1.0f, 0.1f}, 0.3f);     // bottom edge
    add({319, 0}, {319, 120}, {0.1f, 1.0f, 0.1f}, 0.003f);   // right edge, very faint
    add({100, 150}, {180, 110}, {0.1f, 1.0f, 0.1f}, 1.5f);
    add({100, 110}, {180, 150}, {0.1f, 1.0f, 0.1f}, 1.5f);
    return f;
}

bz::scene::FrameList empty_frame(double time_s) {
    bz::scene::FrameList f;
    f.time_s = time_s;
    return f;
}

struct Frames {
    std::vector<std::uint8_t> sparse, dense;
};

// The same frames through two renderers that differ only in the composite.
Frames render_both(bz::render::RenderSettings s, int frames) {
    bz::scene::MeshLibrary meshes;
    s.sparse_composite = true;
    bz::render::Renderer sparse(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
    s.sparse_composite = false;
    bz::render::Renderer dense(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
    for (int i = 0; i < frames; ++i) {
        const auto f = scattered_lines(i / 60.0, 7.0f * static_cast<float>(i));
        sparse.render(f, meshes, bz::render::Renderer::kOffscreen);
        dense.render(f, meshes, bz::render::Renderer::kOffscreen);
    }
    return {sparse.read_color(), dense.read_color()};
}

void expect_same_picture(const Frames& f, const char* what) {
    ASSERT_EQ(f.sparse.size(), f.dense.size());
    int worst = 0;
    std::size_t lit = 0;
    for (std::size_t i = 0; i < f.dense.size(); ++i) {
        worst = std::max(worst, std::abs(int{f.sparse[i]} - int{f.dense[i]}));
        if (i % 4 != 3 && f.dense[i] > 0) ++lit;
    }
    EXPECT_LE(worst, 1) << what << ": the sparse composite differs from the dense one";
    // The frame is mostly black, but not all of it: the comparison means something.
    EXPECT_GT(lit, f.dense.size() / 100) << what;
    EXPECT_LT(lit, f.dense.size() * 3 / 4) << what;
}

class SparseCompositeTest : public bz::test::GlTest {};

}  // namespace

TEST_F(SparseCompositeTest, ClassicBeamMatchesTheDenseComposite) {
    expect_same_picture(render_both(bz::render::preset("balanced"), 1), "classic, balanced");
    expect_same_picture(render_both(bz::render::preset("high"), 1),
                        "classic, high (half-res bloom)");
}

TEST_F(SparseCompositeTest, MameBeamWithPhosphorAndOverlayMatchesTheDenseComposite) {
    auto s = bz::render::preset("balanced");
    s.beam = bz::render::beam_look("mame");
    expect_same_picture(render_both(s, 4), "mame, moving lines on the phosphor");
    s.beam.overlay = true;
    expect_same_picture(render_both(s, 2), "mame with the overlay");
}

// The phosphor is computed by the composite where it shades: with the sparse composite, a
// trail must fade and vanish where nothing is lit any more, in the tiles the lines left, and
// the stored picture must equal the dense composite's every frame.
TEST_F(SparseCompositeTest, PhosphorTrailsMatchTheDenseCompositeWhileLinesJumpAround) {
    auto s = bz::render::preset("balanced");
    s.beam = bz::render::beam_look("mame");
    s.beam.persistence_ms = 30.0f;
    bz::scene::MeshLibrary meshes;
    s.sparse_composite = true;
    bz::render::Renderer sparse(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
    s.sparse_composite = false;
    bz::render::Renderer dense(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
    for (int i = 0; i < 12; ++i) {
        // Two frames here, two frames 100 px away, then nothing for the last four.
        const auto f = i < 8 ? scattered_lines(i / 60.0, (i / 2) % 2 == 0 ? 0.0f : 100.0f)
                             : empty_frame(i / 60.0);
        sparse.render(f, meshes, bz::render::Renderer::kOffscreen);
        dense.render(f, meshes, bz::render::Renderer::kOffscreen);
        EXPECT_EQ(sparse.read_picture_hdr(), dense.read_picture_hdr())
            << "phosphor picture, frame " << i;
        const auto a = sparse.read_color(), b = dense.read_color();
        int worst = 0;
        for (std::size_t k = 0; k < a.size(); ++k)
            worst = std::max(worst, std::abs(int{a[k]} - int{b[k]}));
        EXPECT_LE(worst, 1) << "frame " << i;
    }
}

TEST_F(SparseCompositeTest, PhosphorWithBloomDecaysAsExpOfElapsedTime) {
    auto s = bz::render::preset("balanced");
    s.beam.phosphor = bz::render::PhosphorDecay::exponential;
    s.beam.persistence_ms = 100.0f;
    bz::scene::MeshLibrary meshes;
    for (const double fps : {30.0, 144.0}) {
        bz::render::Renderer r(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
        bz::scene::FrameList lit;
        lit.hud.push_back(
            {sparse_hud_at(60, 120), sparse_hud_at(260, 120), {0.0f, 1.0f, 0.0f}, 1.0f});
        r.render(lit, meshes, bz::render::Renderer::kOffscreen);
        const std::size_t centre = (static_cast<std::size_t>(120) * kSparseW + 160) * 4 + 1;
        const float first = r.read_picture_hdr()[centre];
        ASSERT_GT(first, 0.5f);
        const int frames = static_cast<int>(std::lround(fps / 6.0));  // 1/6 s
        for (int i = 1; i <= frames; ++i) {
            r.render(empty_frame(i / fps), meshes, bz::render::Renderer::kOffscreen);
        }
        const double left = r.read_picture_hdr()[centre] / static_cast<double>(first);
        EXPECT_NEAR(left / std::exp(-(1.0 / 6.0) / 0.1), 1.0, 0.01) << fps << " fps";
    }
}

TEST_F(SparseCompositeTest, SizesTheBloomDoesNotDivideFallBackToTheDenseComposite) {
    auto s = bz::render::preset("balanced");  // quarter-resolution bloom
    bz::scene::MeshLibrary meshes;
    const auto f = scattered_lines(0.0, 0.0f);
    std::vector<std::uint8_t> pictures[2];
    for (const bool sparse : {true, false}) {
        s.sparse_composite = sparse;
        bz::render::Renderer r(s, kSparseW + 3, kSparseH + 1, bz::gl::TimingMethod::off);
        r.render(f, meshes, bz::render::Renderer::kOffscreen);
        pictures[sparse ? 0 : 1] = r.read_color();
    }
    EXPECT_EQ(pictures[0], pictures[1]);
}

// The composite updates the picture in place and stores only where a pixel changed, and the
// sparse composite shades only the tiles lit last frame or now: a trail must still fade to
// exact black everywhere (no forgotten texel keeps a remnant), and lines lit again on that
// black must give the very picture and frame they gave on fresh targets.
TEST_F(SparseCompositeTest, InPlacePhosphorFadesToExactBlackAndLightsAgainAsTheFirstTime) {
    bz::scene::MeshLibrary meshes;
    for (const auto decay :
         {bz::render::PhosphorDecay::exponential, bz::render::PhosphorDecay::power_law}) {
        for (const bool sparse : {true, false}) {
            auto s = bz::render::preset("balanced");
            s.beam = bz::render::beam_look("mame");
            s.beam.phosphor = decay;
            s.beam.persistence_ms = 30.0f;
            s.beam.power_law_exponent = 3.0f;  // at 1/4096 after about 2 s, not minutes
            s.sparse_composite = sparse;
            const char* what = sparse ? "sparse" : "dense";
            bz::render::Renderer r(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
            const auto lines = scattered_lines(0.0, 0.0f);
            r.render(lines, meshes, bz::render::Renderer::kOffscreen);
            const std::vector<float> first_picture = r.read_picture_hdr();
            const std::vector<std::uint8_t> first_frame = r.read_color();
            ASSERT_GT(std::count_if(first_picture.begin(), first_picture.end(),
                                    [](float v) { return v > 0.0f; }),
                      100)
                << what;
            // 4 s of empty frames, 0.1 s apart (under the 0.25 s cap on one step).
            double t = 0.0;
            for (int i = 1; i <= 40; ++i) {
                t = i * 0.1;
                r.render(empty_frame(t), meshes, bz::render::Renderer::kOffscreen);
                if (i == 1) {
                    const auto p = r.read_picture_hdr();
                    EXPECT_TRUE(std::any_of(p.begin(), p.end(), [](float v) { return v > 0.0f; }))
                        << what << ": the trail is gone after one step already";
                }
            }
            const std::vector<float> faded = r.read_picture_hdr();
            EXPECT_EQ(std::count_if(faded.begin(), faded.end(), [](float v) { return v != 0.0f; }),
                      0)
                << what << ": the picture (colour and age) is not exactly black";
            const std::vector<std::uint8_t> dark = r.read_color();
            std::size_t lit_bytes = 0;
            for (std::size_t i = 0; i < dark.size(); ++i)
                lit_bytes += (i % 4 != 3 && dark[i] != 0) ? 1 : 0;
            EXPECT_EQ(lit_bytes, 0u) << what << ": the frame is not black";
            r.render(scattered_lines(t + 0.1, 0.0f), meshes, bz::render::Renderer::kOffscreen);
            EXPECT_EQ(r.read_picture_hdr(), first_picture)
                << what << ": lit again, another picture";
            EXPECT_EQ(r.read_color(), first_frame) << what << ": lit again, another frame";
        }
    }
}

// The glow persists with the phosphor (shaders/beam/glow_persistence.glsl): beside a line that
// went out, where the picture itself is black, the glow fades over the next frames instead of
// vanishing at once; without the phosphor it vanishes at once, and a frame drawn without bloom
// leaves no stale glow for the next one to bring back.
TEST_F(SparseCompositeTest, GlowBesideALineThatWentOutFadesWithThePhosphor) {
    bz::scene::MeshLibrary meshes;
    bz::scene::FrameList lit;
    lit.hud.push_back({sparse_hud_at(60, 120), sparse_hud_at(260, 120), {0.2f, 1.0f, 0.2f}, 1.5f});
    const auto glow_beside = [&](bz::render::Renderer& r) {
        const std::vector<std::uint8_t> c = r.read_color();
        return int{c[(static_cast<std::size_t>(120 + 4) * kSparseW + 160) * 4 + 1]};  // 4 px below
    };
    const auto picture_beside = [&](bz::render::Renderer& r) {
        return r.read_picture_hdr()[(static_cast<std::size_t>(120 + 4) * kSparseW + 160) * 4 + 1];
    };
    for (const bool phosphor : {true, false}) {
        auto s = bz::render::preset("balanced");
        s.beam = bz::render::beam_look("mame");
        s.beam.persistence_ms = 100.0f;
        s.hud_glow = true;  // the HUD line stands for a glowing beam line
        if (!phosphor) s.beam.phosphor = bz::render::PhosphorDecay::off;
        bz::render::Renderer r(s, kSparseW, kSparseH, bz::gl::TimingMethod::off);
        r.render(lit, meshes, bz::render::Renderer::kOffscreen);
        const int first = glow_beside(r);
        ASSERT_GT(first, 8) << "the line's glow reaches 4 px";
        EXPECT_EQ(picture_beside(r), 0.0f) << "4 px off, the picture itself is black";
        r.render(empty_frame(1.0 / 60.0), meshes, bz::render::Renderer::kOffscreen);
        const int next = glow_beside(r);
        if (!phosphor) {
            EXPECT_EQ(next, 0) << "without the phosphor the glow goes out with the line";
            continue;
        }
        EXPECT_GT(next, 0) << "the glow went out at once";
        EXPECT_LT(next, first) << "the glow did not fade";
        // One frame without bloom: the glow history is stale afterwards.
        auto dark = s;
        dark.bloom_strength = 0.0f;
        r.set_settings(dark);
        r.render(empty_frame(2.0 / 60.0), meshes, bz::render::Renderer::kOffscreen);
        r.set_settings(s);
        r.render(empty_frame(3.0 / 60.0), meshes, bz::render::Renderer::kOffscreen);
        EXPECT_EQ(glow_beside(r), 0) << "a stale glow came back after a frame without bloom";
    }
}
