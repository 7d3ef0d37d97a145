// Every style on a real model (Wuson, from Debian's assimp-testmodels): pixel statistics in
// regions where there must be fill, lines or halo, and where there must be nothing but the
// background. The regions come from a CPU rasteriser of the model and the exact vector line
// mask, not from the frame under test. Frames go to build/test-out/style_*.png.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <set>

#include "core/image_io.h"
#include "geometry/generated/primitives.h"
#include "geometry/import/import.h"
#include "render/camera/camera_framing.h"
#include "render/render_fixture.h"
#include "render/style_regions.h"
#include "render/styles/style_def.h"
#include "support/tree_paths.h"

using bz::scene::Style;
using bz::test::Region;
using bz::test::Rgb;

namespace {

constexpr const char* kModel = "/usr/share/assimp/models/PLY/Wuson.ply";
const glm::vec3 kObjectColour{0.2f, 1.0f, 0.3f};  // DrawItem's default (the vector green)

class StyleTest : public bz::test::RenderTest {
  protected:
    void SetUp() override {
        settings = bz::render::preset("balanced");
        RenderTest::SetUp();
        ASSERT_TRUE(std::filesystem::exists(kModel))
            << "install assimp-testmodels (tools/install-deps)";
        model = add_mesh(kModel, bz::geo::import_model(kModel));
        add_item(model);
        frame.items.back().smooth = true;
        frame.camera =
            bz::render::frame_bounds(meshes.bounds(model), 50.0, double(kWidth) / kHeight);
        frame.style = Style::vector;
        lines = bz::test::from_mask(mask().pixels, kWidth, kHeight);  // the exact visible lines
        covered = bz::test::coverage(frame, meshes, kWidth, kHeight);
    }

    std::vector<std::uint8_t> draw(Style style, const std::string& name) {
        frame.style = style;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        std::vector<std::uint8_t> rgba = renderer->read_color();
        const auto dir = bz::test::binary_dir() / "test-out";
        std::filesystem::create_directories(dir);
        bz::write_png(dir / ("style_" + name + ".png"), bz::Image{kWidth, kHeight, 4, rgba});
        return rgba;
    }

    // Far from the model: nothing but the style's background.
    void expect_background_far_away(const std::vector<std::uint8_t>& rgba, Style style,
                                    int margin) {
        const glm::vec3 bg = bz::render::style_def(style).background;
        const Region far = bz::test::inverted(bz::test::dilated(covered, margin));
        ASSERT_GT(far.count(), 10000u);
        EXPECT_GT(bz::test::share(far, rgba,
                                  [&](const Rgb& c) {
                                      return std::abs(c.r - bg.r) < 0.01f &&
                                             std::abs(c.g - bg.g) < 0.01f &&
                                             std::abs(c.b - bg.b) < 0.01f;
                                  }),
                  0.999);
    }

    // Deep inside the model and away from every line: fill only.
    Region fill_region() const {
        return bz::test::minus(bz::test::eroded(covered, 3), bz::test::dilated(lines, 5));
    }

    bz::scene::MeshId model = 0;
    Region lines;
    Region covered;
};

bool green_hue(const Rgb& c) {
    return c.g > c.r + 0.05f && c.g > c.b + 0.05f;
}
bool ink(const Rgb& c) {
    return c.luma() < 0.3f;
}

}  // namespace

TEST_F(StyleTest, RegionsAreMeaningful) {
    EXPECT_GT(covered.count(), 4000u);
    EXPECT_GT(lines.count(), 400u);
    EXPECT_GT(fill_region().count(), 2000u);
}

TEST_F(StyleTest, ToonFillsCelBandsAndOutlinesTheLines) {
    const auto rgba = draw(Style::toon, "toon");
    expect_background_far_away(rgba, Style::toon, 4);
    const Region fill = fill_region();
    EXPECT_GT(bz::test::share(fill, rgba, green_hue), 0.98) << "the object's own colour";
    // Cel bands: a handful of flat levels, not a gradient.
    std::set<int> levels;
    std::map<int, int> counts;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            if (fill.at(x, y))
                ++counts[static_cast<int>(
                    std::lround(bz::test::pixel(rgba, kWidth, x, y).g * 255))];
    for (const auto& [g, n] : counts)
        if (n > static_cast<int>(fill.count() / 50)) levels.insert(g);
    EXPECT_GE(levels.size(), 2u);
    EXPECT_LE(levels.size(), 4u);
    // Ink on the exact lines.
    EXPECT_GT(bz::test::share(lines, rgba, ink), 0.8);
}

TEST_F(StyleTest, ToonOneSidedOutlinesLieOutsideTheSilhouette) {
    const auto centred = draw(Style::toon, "toon_centred");
    settings.one_sided_outlines = true;
    const auto one_sided = draw(Style::toon, "toon_one_sided");
    expect_background_far_away(one_sided, Style::toon, 5);
    // Just outside the silhouette: one-sided quads put more ink there than centred ones
    // (which spend half their width inside).
    const Region ring = bz::test::minus(bz::test::dilated(covered, 2), covered);
    EXPECT_GT(bz::test::share(ring, one_sided, ink), bz::test::share(ring, centred, ink));
    EXPECT_GT(bz::test::share(ring, one_sided, ink), 0.6);
}

TEST_F(StyleTest, PopArtFillsFlatColourWithDotsAndAFineOutline) {
    const auto rgba = draw(Style::pop_art, "pop_art");
    expect_background_far_away(rgba, Style::pop_art, 3);
    const Region fill = fill_region();
    EXPECT_GT(bz::test::share(fill, rgba, green_hue), 0.98);
    // Ben-Day dots: darker dots and the lighter base colour both show inside.
    const double dark = bz::test::share(fill, rgba, [](const Rgb& c) { return c.g < 0.5f; });
    const double light = bz::test::share(fill, rgba, [](const Rgb& c) { return c.g > 0.7f; });
    EXPECT_GT(dark, 0.03);
    EXPECT_GT(light, 0.2);
    EXPECT_GT(bz::test::share(lines, rgba, ink), 0.75);
    // Fine: ink stays within a pixel or two of the lines.
    const Region beside = bz::test::minus(bz::test::dilated(lines, 4), bz::test::dilated(lines, 2));
    EXPECT_LT(bz::test::share(bz::test::minus(beside, covered), rgba, ink), 0.05);
}

TEST_F(StyleTest, SketchDrawsStrokesNearTheLinesOnPaper) {
    const auto rgba = draw(Style::sketch, "sketch");
    expect_background_far_away(rgba, Style::sketch, 8);
    const glm::vec3 paper = bz::render::style_def(Style::sketch).background;
    const auto graphite = [&](const Rgb& c) {
        return c.luma() < 0.75f * (0.2126f * paper.r + 0.7152f * paper.g + 0.0722f * paper.b);
    };
    EXPECT_GT(bz::test::share_near(lines, rgba, 3, graphite), 0.6) << "strokes follow the lines";
    EXPECT_LT(bz::test::share(fill_region(), rgba, graphite), 0.03) << "no strokes away from lines";
}

TEST_F(StyleTest, SketchIsStillForAStillCamera) {
    const auto a = draw(Style::sketch, "sketch_a");
    const auto b = draw(Style::sketch, "sketch_b");
    EXPECT_EQ(a, b);
}

TEST_F(StyleTest, SketchStrokesMoveWithTheCameraInsteadOfBoiling) {
    const auto before = draw(Style::sketch, "sketch_pan0");
    // Pan by exactly 3 pixels: the drawing must shift, not be redrawn differently.
    const glm::dvec3 forward = glm::normalize(frame.camera.target - frame.camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, frame.camera.up));
    const double dist = glm::length(frame.camera.target - frame.camera.eye);
    const double px = 2.0 * dist * std::tan(glm::radians(frame.camera.fov_y_deg) * 0.5) / kHeight;
    // A pan moves near and far points by different amounts; rotate instead? A pure sideways
    // move of the eye and target shifts points at the target's depth by exactly 3 px.
    frame.camera.eye += right * (3.0 * px);
    frame.camera.target += right * (3.0 * px);
    const auto after = draw(Style::sketch, "sketch_pan3");
    const glm::vec3 paper = bz::render::style_def(Style::sketch).background;
    const float paper_luma = 0.2126f * paper.r + 0.7152f * paper.g + 0.0722f * paper.b;
    std::size_t strokes = 0, kept = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 3; x < kWidth; ++x) {
            if (bz::test::pixel(before, kWidth, x, y).luma() > 0.7f * paper_luma) continue;
            ++strokes;
            // The model moved 3 px left on screen; allow a pixel of depth parallax.
            bool found = false;
            for (int dx = -4; dx <= -2 && !found; ++dx)
                for (int dy = -1; dy <= 1 && !found; ++dy) {
                    const int u = x + dx, v = y + dy;
                    if (u >= 0 && v >= 0 && v < kHeight &&
                        bz::test::pixel(after, kWidth, u, v).luma() < 0.8f * paper_luma)
                        found = true;
                }
            if (found) ++kept;
        }
    }
    ASSERT_GT(strokes, 300u);
    EXPECT_GT(static_cast<double>(kept) / static_cast<double>(strokes), 0.9);
}

TEST_F(StyleTest, HaloInksTheOutlineAndFadesWhatIsBehindIt) {
    // A red wall behind the model: the halo must lighten it next to the silhouette.
    const auto wall = add_mesh("wall", bz::geo::box(glm::vec3(1.0f)));
    const bz::geo::Bounds b = meshes.bounds(model);
    const glm::dvec3 centre(b.center());
    const glm::dvec3 back = glm::normalize(centre - frame.camera.eye);
    const double r = b.radius();
    // A cube 24 r across whose near side is about 2 r behind the model's centre.
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), centre + back * (14.0 * r));
    m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(12.0 * r));
    add_item(wall, m);
    frame.items.back().color = {1.0f, 0.1f, 0.1f};
    frame.camera.far = glm::length(centre - frame.camera.eye) + 40.0 * r;
    const auto rgba = draw(Style::halo, "halo");
    const Region model_only = bz::test::coverage(
        bz::scene::FrameList{frame.camera, {frame.items.front()}, {}, Style::halo}, meshes, kWidth,
        kHeight);
    // Outside the model's silhouette, where only the wall is: a band next to it and the wall
    // far from it.
    const Region band =
        bz::test::minus(bz::test::dilated(model_only, 7), bz::test::dilated(model_only, 4));
    const Region wall_far = bz::test::inverted(bz::test::dilated(model_only, 30));
    const auto reddish = [](const Rgb& c) { return c.r > c.g + 0.08f; };
    EXPECT_GT(bz::test::share(wall_far, rgba, reddish), 0.9) << "the wall shows its colour";
    EXPECT_LT(bz::test::share(band, rgba, reddish), 0.3)
        << "the halo fades the wall near the model";
    // Ink along the model's outline (its lines next to the wall). Not all of it: the halo of a
    // nearer leg fades the lines of the leg behind it, as it fades the wall.
    const Region outline = bz::test::minus(lines, bz::test::eroded(model_only, 2));
    ASSERT_GT(outline.count(), 100u);
    EXPECT_GT(bz::test::share_near(outline, rgba, 1, ink), 0.7);
}

TEST_F(StyleTest, VectorStylesKeepTheirLook) {
    const auto rgba = draw(Style::vector, "vector");
    // Black screen, bright green lines; far from them only the faintest bloom.
    EXPECT_GT(bz::test::share(lines, rgba, green_hue), 0.9);
    const Region far = bz::test::inverted(bz::test::dilated(covered, 20));
    EXPECT_GT(bz::test::share(far, rgba, [](const Rgb& c) { return c.luma() < 0.03f; }), 0.999);
}

TEST_F(StyleTest, ExactLineStylesShareTheVectorMask) {
    // Toon, pop-art and the halo's centre line are scored with the vector mask; sketch with
    // its own strokes, which stay within its jitter of the lines.
    for (const Style s : {Style::toon, Style::pop_art, Style::halo}) {
        frame.style = s;
        EXPECT_EQ(bz::test::from_mask(mask().pixels, kWidth, kHeight).on, lines.on)
            << bz::scene::style_name(s);
    }
    frame.style = Style::sketch;
    const Region strokes = bz::test::from_mask(mask("sketch").pixels, kWidth, kHeight);
    EXPECT_GT(strokes.count(), lines.count() / 2);
    EXPECT_LT(bz::test::minus(strokes, bz::test::dilated(lines, 5)).count(), strokes.count() / 50);
}
