// The halo style's cubic smoothing (Loviscach): a coarse sphere (6 bands, 8 segments) outlines
// as a polygon without it and as a near circle with it. Measured on the ink: the outer edge of
// the outline stroke, as a radius per angle around the sphere's centre, deviates less from a
// circle (its spread across angles shrinks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/image_io.h"
#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"
#include "support/tree_paths.h"

namespace {

class HaloSmoothingTest : public bz::test::RenderTest {
  protected:
    // Outer ink radius per angle bin, around the image centre (the sphere is centred).
    std::vector<double> outer_radii(bool smoothing, const std::string& name) {
        settings.cubic_smoothing = smoothing;
        renderer->set_settings(settings);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        const std::vector<std::uint8_t> rgba = renderer->read_color();
        const auto dir = bz::test::binary_dir() / "test-out";
        std::filesystem::create_directories(dir);
        bz::write_png(dir / (name + ".png"), bz::Image{kWidth, kHeight, 4, rgba});
        constexpr int kBins = 180;
        std::vector<double> radius(kBins, 0.0);
        const double cx = kWidth * 0.5, cy = kHeight * 0.5;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const std::size_t i = (static_cast<std::size_t>(y) * kWidth + x) * 4;
                const double luma =
                    (0.2126 * rgba[i] + 0.7152 * rgba[i + 1] + 0.0722 * rgba[i + 2]) / 255.0;
                if (luma > 0.45) continue;  // ink only
                const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
                const double a = std::atan2(dy, dx) + M_PI;
                const int bin = std::min(kBins - 1, static_cast<int>(a / (2.0 * M_PI) * kBins));
                radius[static_cast<std::size_t>(bin)] =
                    std::max(radius[static_cast<std::size_t>(bin)], std::hypot(dx, dy));
            }
        }
        return radius;
    }

    static double spread(const std::vector<double>& r) {
        const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
        return *hi - *lo;
    }
};

}  // namespace

TEST_F(HaloSmoothingTest, CoarseSphereOutlineIsRounderWithSmoothing) {
    settings = bz::render::preset("balanced");
    settings.style = bz::scene::Style::halo;
    const auto id = add_mesh("coarse-sphere", bz::geo::uv_sphere(1.0f, 6, 8));
    add_item(id);
    // Looking down the pole axis: the silhouette is the equator, an octagon whose corners lie on
    // the sphere's outline and whose sides cut inside it by R (1 - cos 22.5 deg).
    frame.camera.eye = {0.0, 3.6, 0.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.camera.up = {0.0, 0.0, -1.0};
    frame.camera.fov_y_deg = 45.0;
    const std::vector<double> plain = outer_radii(false, "halo_coarse_sphere_plain");
    const std::vector<double> smooth = outer_radii(true, "halo_coarse_sphere_smooth");
    for (double r : plain) ASSERT_GT(r, 40.0) << "an outline all around";
    for (double r : smooth) ASSERT_GT(r, 40.0) << "an outline all around";
    std::printf("outline radius spread: plain %.2f px, smoothed %.2f px\n", spread(plain),
                spread(smooth));
    EXPECT_LT(spread(smooth), 0.6 * spread(plain))
        << "plain spread " << spread(plain) << " px, smoothed " << spread(smooth) << " px";
}
