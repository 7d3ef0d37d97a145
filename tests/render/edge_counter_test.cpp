// The feature-edge count (FrameStats::feature_edges) read back late: with GPU timer queries
// the renderer reports each frame's count as many frames later as its pass times, so that
// counting never makes the CPU wait in the middle of a frame (render/lines/edge_counter.h).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

using bz::render::LineMethod;
using bz::render::Renderer;
using bz::test::RenderTest;

namespace {

class EdgeCounterTest : public RenderTest {
  protected:
    // Frames of 1, 2, 3, ... spheres in a row: each has more feature edges than the last.
    std::vector<bz::scene::FrameList> growing_frames(int n) {
        const auto sphere = add_mesh("sphere", bz::geo::uv_sphere(0.5f, 8, 16));
        std::vector<bz::scene::FrameList> out;
        bz::scene::FrameList f = frame;
        f.items.clear();
        f.camera.eye = {0.0, 2.0, 9.0};
        f.camera.target = {0.0, 0.0, 0.0};
        for (int i = 0; i < n; ++i) {
            bz::scene::DrawItem item;
            item.mesh = sphere;
            item.model = glm::translate(glm::dmat4(1.0), glm::dvec3(i * 1.2 - 4.0, 0.0, 0.0));
            f.items.push_back(item);
            out.push_back(f);
        }
        return out;
    }

    // Each frame's count as a renderer timed with glFinish reports it (read at once).
    std::vector<std::size_t> counts_read_at_once(const std::vector<bz::scene::FrameList>& frames,
                                                 const bz::render::RenderSettings& s) {
        Renderer r(s, kWidth, kHeight, bz::gl::TimingMethod::cpu_finish);
        EXPECT_EQ(r.pass_times_latency(), 0);
        std::vector<std::size_t> counts;
        for (const auto& f : frames) {
            r.render(f, meshes, Renderer::kOffscreen);
            counts.push_back(r.stats().feature_edges);
        }
        return counts;
    }
};

}  // namespace

TEST_F(EdgeCounterTest, WithTimerQueriesEachCountArrivesWithItsFramesPassTimes) {
    const std::vector<bz::scene::FrameList> frames = growing_frames(8);
    for (const LineMethod method : bz::render::feature_line_methods()) {
        SCOPED_TRACE(bz::render::line_method_name(method));
        bz::render::RenderSettings s = bz::render::preset("balanced");
        s.method = method;
        s.count_edges = true;
        const std::vector<std::size_t> at_once = counts_read_at_once(frames, s);
        for (std::size_t i = 1; i < at_once.size(); ++i) {
            EXPECT_GT(at_once[i], at_once[i - 1]) << "frame " << i << " adds a sphere";
        }

        Renderer late(s, kWidth, kHeight, bz::gl::TimingMethod::gpu_queries);
        const int latency = late.pass_times_latency();
        ASSERT_GT(latency, 0);
        // The frames, then `latency` more of the last one, as bench draws to flush the results.
        for (std::size_t i = 0; i < frames.size() + static_cast<std::size_t>(latency); ++i) {
            late.render(frames[std::min(i, frames.size() - 1)], meshes, Renderer::kOffscreen);
            const std::size_t lag = static_cast<std::size_t>(latency);
            const std::size_t expected = i >= lag ? at_once[i - lag] : 0;
            EXPECT_EQ(late.stats().feature_edges, expected) << "after frame " << i;
        }
    }
}
