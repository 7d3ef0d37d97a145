// The benchmark's plots as pictures: labels placed where a reader can read them.
#include "app/bench/bench_plots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "app/plot/plot_chart.h"
#include "core/image_io.h"
#include "support/scratch_dir.h"

namespace {

// A pixel in one of the series colours rather than the grey ink or the white paper.
bool coloured(const bz::Image& img, int x, int y) {
    const int r = img.at(x, y, 0), g = img.at(x, y, 1), b = img.at(x, y, 2);
    return std::max({r, g, b}) - std::min({r, g, b}) > 40;
}

}  // namespace

TEST(TradeoffPlot, LabelsOfPointsCrowdedAtTheTopStayOutOfTheTitle) {
    // Most configurations score F1 0.995-1.0: their points sit on the plot's top edge, right
    // under the title, and their labels must find room below it, not over it.
    bz::test::ScratchDir dir("bz_plot");
    std::vector<bz::app::TradeoffPoint> points;
    for (int i = 0; i < 16; ++i) {
        points.push_back({"configuration-" + std::to_string(i), 10.0 + 0.4 * i, 1.0, 0.999});
    }
    points.push_back({"slow-outlier", 40.0, 0.95, 0.9});  // spreads the axes like a real sweep
    const bz::scene::VectorFont font = bz::scene::VectorFont::load_default();
    const auto out = dir.path() / "tradeoff.png";
    bz::app::plot_tradeoff(points, "speed vs accuracy, crowded", &font, out);
    const bz::Image img = bz::read_png(out, 4);

    // Rows from the top down to the title's lowest letters (bz::app::Chart::title_bottom): only
    // the title's grey ink and paper there; every label is drawn in its series colour.
    const int title_band =
        img.height - static_cast<int>(static_cast<float>(img.height) - 30.0f -
                                      bz::app::Chart::kTitleHeight * 0.35f - 2.0f);
    ASSERT_GT(title_band, 20);
    int in_band = 0;
    for (int y = 0; y < title_band; ++y) {
        for (int x = 0; x < img.width; ++x) in_band += coloured(img, x, y) ? 1 : 0;
    }
    EXPECT_EQ(in_band, 0) << "label pixels over the title";
    // The labels were drawn: coloured pixels beyond the points' discs and bars.
    int total = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) total += coloured(img, x, y) ? 1 : 0;
    }
    EXPECT_GT(total, 3000);
}
