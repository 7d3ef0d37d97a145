// Masks of analytic scenes, checked against exact projections of the edges that must show.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "render/render_fixture.h"

using bz::test::expected_mask;
using bz::test::Mask;
using bz::test::RenderTest;
using Segments = std::vector<std::pair<glm::dvec3, glm::dvec3>>;

namespace {

// The 12 edges of an axis-aligned cube of half size h, split into the 9 seen from a camera in
// the (+,+,+) octant and the 3 that meet at the hidden corner (-h,-h,-h).
void cube_edges(double h, Segments& visible, Segments& hidden) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int s1 = -1; s1 <= 1; s1 += 2) {
            for (int s2 = -1; s2 <= 1; s2 += 2) {
                glm::dvec3 a(0.0), b(0.0);
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                a[axis] = -h;
                b[axis] = h;
                a[u] = b[u] = s1 * h;
                a[v] = b[v] = s2 * h;
                (s1 < 0 && s2 < 0 ? hidden : visible).push_back({a, b});
            }
        }
    }
}

int connected_components(const Mask& m) {
    std::vector<int> label(m.pixels.size(), 0);
    int components = 0;
    for (int y = 0; y < m.height; ++y) {
        for (int x = 0; x < m.width; ++x) {
            if (!m.lit(x, y) || label[static_cast<std::size_t>(y * m.width + x)]) continue;
            ++components;
            std::vector<std::pair<int, int>> stack{{x, y}};
            label[static_cast<std::size_t>(y * m.width + x)] = components;
            while (!stack.empty()) {
                auto [cx, cy] = stack.back();
                stack.pop_back();
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = cx + dx, ny = cy + dy;
                        if (!m.lit(nx, ny) || label[static_cast<std::size_t>(ny * m.width + nx)])
                            continue;
                        label[static_cast<std::size_t>(ny * m.width + nx)] = components;
                        stack.push_back({nx, ny});
                    }
                }
            }
        }
    }
    return components;
}

// Flood-fills unlit pixels (4-connected) from the image border; true if (x, y) is reached.
bool reachable_from_border(const Mask& m, int tx, int ty) {
    std::vector<std::uint8_t> seen(m.pixels.size(), 0);
    std::vector<std::pair<int, int>> stack;
    for (int x = 0; x < m.width; ++x) stack.insert(stack.end(), {{x, 0}, {x, m.height - 1}});
    for (int y = 0; y < m.height; ++y) stack.insert(stack.end(), {{0, y}, {m.width - 1, y}});
    while (!stack.empty()) {
        auto [x, y] = stack.back();
        stack.pop_back();
        if (x < 0 || y < 0 || x >= m.width || y >= m.height || m.lit(x, y)) continue;
        auto& s = seen[static_cast<std::size_t>(y * m.width + x)];
        if (s) continue;
        s = 1;
        if (x == tx && y == ty) return true;
        stack.insert(stack.end(), {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}});
    }
    return false;
}

}  // namespace

class CubeMaskTest : public RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        add_item(add_mesh("cube", bz::geo::box(glm::vec3(0.5f))));
        frame.camera.eye = {1.9, 1.4, 2.6};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 40.0;
        frame.camera.near = 0.1;
        frame.camera.far = 100.0;
        cube_edges(0.5, visible, hidden);
    }
    Segments visible, hidden;
};

TEST_F(CubeMaskTest, LightsItsNineVisibleEdgesAndNothingElse) {
    for (const char* name : {"fast", "balanced", "high"}) {
        settings = bz::render::preset(name);
        const Mask got = mask(std::string("cube_") + name);
        const Mask want = expected_mask(frame.camera, kWidth, kHeight, visible);
        const auto s = bz::test::score_masks(got, want, 1);
        EXPECT_EQ(s.precision, 1.0) << name << ": lit pixels off the 9 visible edges";
        EXPECT_GE(s.recall, 0.99) << name << ": visible edge pixels missing";
        EXPECT_GT(s.test_count, 300) << name;
    }
}

TEST_F(CubeMaskTest, DepthFormatsAgree) {
    const Mask want = expected_mask(frame.camera, kWidth, kHeight, visible);
    settings.depth = bz::render::DepthFormat::conventional_d24;
    const auto s = bz::test::score_masks(mask("cube_d24"), want, 1);
    EXPECT_EQ(s.precision, 1.0);
    EXPECT_GE(s.recall, 0.99);
}

TEST_F(CubeMaskTest, ArcadeStyleShowsHiddenEdgesToo) {
    frame.style = bz::scene::LineStyle::arcade;
    Segments all = visible;
    all.insert(all.end(), hidden.begin(), hidden.end());
    const auto s = bz::test::score_masks(mask("cube_arcade"),
                                         expected_mask(frame.camera, kWidth, kHeight, all), 1);
    EXPECT_EQ(s.precision, 1.0);
    EXPECT_GE(s.recall, 0.99);
}

TEST_F(CubeMaskTest, CreaseThresholdAboveNinetyDegreesLeavesOnlyTheOutline) {
    settings.crease_angle_deg = 95.0f;
    const Mask got = mask("cube_outline");
    // The three edges meeting at the near corner (1,1,1)/2 are creases between front faces.
    Segments outline;
    for (auto& e : visible) {
        const bool at_near_corner = (e.first == glm::dvec3(0.5) || e.second == glm::dvec3(0.5));
        if (!at_near_corner) outline.push_back(e);
    }
    ASSERT_EQ(outline.size(), 6u);
    const auto s =
        bz::test::score_masks(got, expected_mask(frame.camera, kWidth, kHeight, outline), 1);
    EXPECT_EQ(s.precision, 1.0);
    EXPECT_GE(s.recall, 0.99);
}

TEST_F(RenderTest, SphereSilhouetteIsOneClosedLoop) {
    add_item(add_mesh("sphere", bz::geo::uv_sphere(1.0f, 24, 48)));
    frame.camera.eye = {0.0, 0.8, 4.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.camera.fov_y_deg = 45.0;
    for (const char* name : {"fast", "balanced", "high"}) {
        settings = bz::render::preset(name);
        const Mask m = mask(std::string("sphere_") + name);
        EXPECT_EQ(connected_components(m), 1) << name;
        EXPECT_FALSE(reachable_from_border(m, kWidth / 2, kHeight / 2))
            << name << ": loop is not closed";
        EXPECT_GT(m.count(), 200) << name;
    }
}

TEST_F(RenderTest, ObjectHiddenBehindAnotherAddsNoPixels) {
    const auto big = add_mesh("big", bz::geo::box(glm::vec3(1.0f)));
    const auto small = add_mesh("small", bz::geo::uv_sphere(0.4f, 12, 24));
    frame.camera.eye = {0.0, 0.4, 5.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    add_item(big);
    const Mask alone = mask("hidden_alone");
    add_item(small, glm::translate(glm::dmat4(1.0), glm::dvec3(0.2, 0.0, -3.0)));
    const Mask both = mask("hidden_both");
    EXPECT_EQ(alone.pixels, both.pixels);
    // The small object is really there: without occlusion it shows.
    frame.style = bz::scene::LineStyle::arcade;
    EXPECT_GT(mask().count(), alone.count() + 50);
}

TEST_F(RenderTest, EdgesCrossingTheNearPlaneAreClippedNotGarbled) {
    // A floorboard from z = -20 to z = +20 passing under a camera at the origin looking -z:
    // half of it is behind the camera. Seen from above, only its top face shows.
    add_item(add_mesh("board", bz::geo::box(glm::vec3(0.5f, 0.1f, 20.0f))),
             glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -1.1, 0.0)));
    frame.camera.eye = {0.0, 0.0, 0.0};
    frame.camera.target = {0.0, 0.0, -1.0};
    frame.camera.fov_y_deg = 90.0;
    frame.camera.near = 0.1;
    frame.camera.far = 100.0;
    const Segments top = {{{-0.5, -1.0, -20.0}, {-0.5, -1.0, 20.0}},
                          {{0.5, -1.0, -20.0}, {0.5, -1.0, 20.0}},
                          {{-0.5, -1.0, -20.0}, {0.5, -1.0, -20.0}}};
    const Mask want = expected_mask(frame.camera, kWidth, kHeight, top);
    for (auto depth :
         {bz::render::DepthFormat::reversed_f32, bz::render::DepthFormat::conventional_d24}) {
        settings.depth = depth;
        const auto s = bz::test::score_masks(mask("near_plane"), want, 1);
        EXPECT_GE(s.precision, 0.99);
        EXPECT_GE(s.recall, 0.97);
    }
    save_color("near_plane");
}

TEST_F(RenderTest, GeometryWhollyBehindTheCameraDrawsNothing) {
    add_item(add_mesh("cube", bz::geo::box(glm::vec3(1.0f))),
             glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, 10.0)));
    frame.camera.eye = {0.0, 0.0, 0.0};
    frame.camera.target = {0.0, 0.0, -1.0};
    settings.frustum_culling = false;  // make the geometry shader see it
    EXPECT_EQ(mask().count(), 0);
}

TEST_F(RenderTest, InsideAClosedBoxItsInnerEdgesShow) {
    // Seen from inside, every face of a closed box is back-facing; the renderer may skip back
    // faces only when the eye is outside, so the room's edges must still be drawn here.
    add_item(add_mesh("room", bz::geo::box(glm::vec3(4.0f))));
    frame.camera.eye = {0.0, 0.0, 0.0};
    frame.camera.target = {-4.0, -4.0, -4.0};
    frame.camera.fov_y_deg = 90.0;
    frame.camera.near = 0.05;
    // The three edges that meet at the far corner (-4,-4,-4) are in view.
    const Segments corner = {
        {{-4, -4, -4}, {4, -4, -4}}, {{-4, -4, -4}, {-4, 4, -4}}, {{-4, -4, -4}, {-4, -4, 4}}};
    const auto s = bz::test::score_masks(mask("room_inside"),
                                         expected_mask(frame.camera, kWidth, kHeight, corner), 1);
    EXPECT_GE(s.recall, 0.9);
    EXPECT_GT(s.test_count, 100);
}

TEST_F(RenderTest, SkippingBackFacesOfClosedMeshesChangesNoPixel) {
    // Many closed spheres and boxes seen from outside: the mask with the back-face shortcut
    // equals the arcade-free reference drawn from an open copy of the same meshes (an open
    // mesh never takes the shortcut).
    const auto closed_sphere = add_mesh("s", bz::geo::uv_sphere(1.0f, 12, 24));
    bz::geo::TriMesh open = bz::geo::uv_sphere(1.0f, 12, 24);
    open.positions.push_back({50.0f, 50.0f, 50.0f});
    open.positions.push_back({50.1f, 50.0f, 50.0f});
    open.positions.push_back({50.0f, 50.1f, 50.0f});
    const auto n = static_cast<std::uint32_t>(open.positions.size());
    open.indices.insert(open.indices.end(), {n - 3, n - 2, n - 1});  // a far-away loose triangle
    const auto open_sphere = add_mesh("o", open);
    frame.camera.eye = {0.0, 3.0, 9.0};
    frame.camera.target = {0.0, 0.0, 0.0};
    frame.camera.far = 60.0;  // the loose triangle lies beyond the far plane
    for (int i = 0; i < 4; ++i)
        add_item(closed_sphere, glm::translate(glm::dmat4(1.0), glm::dvec3(i * 1.5 - 2.25, 0, -i)));
    const auto with_shortcut = mask("shortcut");
    frame.items.clear();
    for (int i = 0; i < 4; ++i)
        add_item(open_sphere, glm::translate(glm::dmat4(1.0), glm::dvec3(i * 1.5 - 2.25, 0, -i)));
    const auto without = mask("no_shortcut");
    EXPECT_GT(with_shortcut.count(), 300);
    EXPECT_EQ(with_shortcut.pixels, without.pixels);
}
