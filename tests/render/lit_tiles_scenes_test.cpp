// The sparse composite over the lit-tile list against the every-pixel composite on scenes of
// real models, in both line methods and both beam looks, with the camera moving so that the
// phosphor's trails and the glow's history cross tiles that are no longer lit: the frames
// must be the same, byte for byte, and so must the phosphor pictures. One exception, which is
// not the composite's: the compute method appends its records in whatever order the atomics
// give, and the `mame` look adds lines in half floats, so two renderers' beam images differ
// by a rounding step here and there even with both composites dense (measured on the milk
// truck: up to 26 of about 9,000 lit pixels, by up to 3 8-bit steps, from run to run; dense
// against dense, the same). There the frames may differ by at most 8 steps on at most 2 % of
// the lit pixels: a tile the list missed would blank its glow (tens of steps on 256 pixels).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "geometry/import/import.h"
#include "geometry/line_mesh/line_mesh.h"
#include "render/camera/camera_framing.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace {

constexpr int kScenesW = 320;
constexpr int kScenesH = 240;

struct Difference {
    int worst = 0;           // largest difference of one channel, in 8-bit steps
    std::size_t pixels = 0;  // pixels where any channel differs
    std::size_t lit = 0;     // pixels the every-pixel composite lit
};

Difference compare(const std::vector<std::uint8_t>& sparse,
                   const std::vector<std::uint8_t>& dense) {
    Difference d;
    for (std::size_t p = 0; p + 3 < dense.size(); p += 4) {
        bool differs = false, lit = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const int delta = std::abs(int{sparse[p + c]} - int{dense[p + c]});
            d.worst = std::max(d.worst, delta);
            differs = differs || delta != 0;
            lit = lit || dense[p + c] != 0;
        }
        d.pixels += differs ? 1 : 0;
        d.lit += lit ? 1 : 0;
    }
    return d;
}

class LitTilesScenesTest : public bz::test::GlTest {};

}  // namespace

TEST_F(LitTilesScenesTest, SparseFramesEqualEveryPixelFramesOnRealModelsInEveryLookAndMethod) {
    const char* models[] = {"/usr/share/assimp/models/PLY/Wuson.ply",
                            "/usr/share/assimp/models/OBJ/spider.obj",
                            "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"};
    for (const char* path : models) {
        bz::scene::MeshLibrary meshes;
        const bz::scene::MeshId id =
            meshes.add(path, bz::geo::build_line_mesh(bz::geo::import_model(path)));
        bz::scene::FrameList frame;
        frame.items.push_back({});
        frame.items.back().mesh = id;
        frame.items.back().model = glm::dmat4(1.0);
        const bz::scene::Camera framed =
            bz::render::frame_bounds(meshes.bounds(id), 50.0, double(kScenesW) / kScenesH);
        for (const auto method : bz::render::feature_line_methods()) {
            for (const char* look : {"classic", "mame"}) {
                SCOPED_TRACE(std::string(path) + ", " + bz::render::line_method_name(method) +
                             ", " + look);
                auto s = bz::render::preset("balanced");
                s.method = method;
                s.beam = bz::render::beam_look(look);
                s.sparse_composite = true;
                bz::render::Renderer sparse(s, kScenesW, kScenesH, bz::gl::TimingMethod::off);
                s.sparse_composite = false;
                bz::render::Renderer dense(s, kScenesW, kScenesH, bz::gl::TimingMethod::off);
                // The camera swings around the model, a little further each frame.
                for (int i = 0; i < 5; ++i) {
                    frame.time_s = i / 60.0;
                    frame.camera = framed;
                    const glm::dvec3 arm = framed.eye - framed.target;
                    const double a = 0.25 * i;
                    frame.camera.eye =
                        framed.target + glm::dvec3(arm.x * std::cos(a) - arm.z * std::sin(a), arm.y,
                                                   arm.x * std::sin(a) + arm.z * std::cos(a));
                    sparse.render(frame, meshes, bz::render::Renderer::kOffscreen);
                    dense.render(frame, meshes, bz::render::Renderer::kOffscreen);
                    const Difference d = compare(sparse.read_color(), dense.read_color());
                    EXPECT_GT(d.lit, static_cast<std::size_t>(kScenesW * kScenesH / 100))
                        << "frame " << i;
                    const bool blend_order =
                        method == bz::render::LineMethod::compute && std::string(look) == "mame";
                    if (blend_order) {
                        EXPECT_LE(d.worst, 8) << "frame " << i;
                        EXPECT_LE(d.pixels, d.lit / 50) << "frame " << i;
                        continue;
                    }
                    EXPECT_EQ(d.worst, 0) << "frame " << i;
                    EXPECT_EQ(d.pixels, 0u) << "frame " << i;
                    EXPECT_EQ(sparse.read_picture_hdr(), dense.read_picture_hdr()) << "frame " << i;
                    // The list is what made the difference: it does not cover the screen.
                    const auto tiles = sparse.read_lit_tiles();
                    EXPECT_FALSE(tiles.empty()) << "frame " << i;
                }
            }
        }
    }
}
