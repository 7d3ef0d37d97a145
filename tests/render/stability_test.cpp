// Numerical stability of the line pipeline at extreme values: every scene is rendered, its
// mask scored against the exact CPU reference (F1 at 1 px), and the HDR line target checked
// for NaN and Inf. Each case runs with both depth formats; the default (reversed-Z float) must
// pass them all. What the 24-bit format does is printed ("[stability] ...") for the table in
// docs/measurements/stability.md and asserted only where it is known to hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/reference/mask_score.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

namespace {

using bz::render::DepthFormat;
namespace geo = bz::geo;

constexpr double kMinF1 = 0.97;

struct Outcome {
    geo::MaskScore score;
    bool finite = true;
};

const char* depth_name(DepthFormat d) {
    return d == DepthFormat::reversed_f32 ? "reversed_f32" : "conventional_d24";
}

class StabilityTest : public bz::test::RenderTest {
  protected:
    void SetUp() override {
        RenderTest::SetUp();
        // The reference is full detail: no distance LOD on the GPU side either.
        settings.lod = false;
    }

    // A new mesh library reuses ids, so the renderer (and its GPU mesh cache) starts afresh.
    void reset_scene() {
        meshes = {};
        frame.items.clear();
        renderer = std::make_unique<bz::render::Renderer>(settings, kWidth, kHeight,
                                                          bz::gl::TimingMethod::off);
    }

    // Renders the current frame with `depth`, scores it against the reference, checks the
    // HDR target, and prints one table row.
    Outcome check(const std::string& name, DepthFormat depth) {
        settings.depth = depth;
        const bz::test::Mask gpu = mask(name + "_" + depth_name(depth));
        const std::vector<std::uint8_t> ref =
            bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight);
        Outcome o;
        o.score = geo::score_masks(gpu.pixels, ref, kWidth, kHeight, 1);
        renderer->render(frame, meshes, bz::render::Renderer::kOffscreen);
        for (float v : renderer->read_lines_hdr()) o.finite = o.finite && std::isfinite(v);
        std::printf("[stability] %-28s %-16s F1 %.4f  P %.4f  R %.4f  (gpu %zu px, ref %zu px)%s\n",
                    name.c_str(), depth_name(depth), o.score.f1, o.score.precision, o.score.recall,
                    o.score.test_lit, o.score.ref_lit, o.finite ? "" : "  NON-FINITE");
        return o;
    }

    // The default format must pass; the other is reported, and must at least stay finite.
    void expect_stable(const std::string& name, bool d24_must_pass = true) {
        const Outcome f32 = check(name, DepthFormat::reversed_f32);
        EXPECT_TRUE(f32.finite) << name;
        EXPECT_GE(f32.score.f1, kMinF1) << name << " (reversed_f32)";
        EXPECT_GT(f32.score.ref_lit, 100u) << name << ": the scene shows too little to test";
        const Outcome d24 = check(name, DepthFormat::conventional_d24);
        EXPECT_TRUE(d24.finite) << name;
        if (d24_must_pass) {
            EXPECT_GE(d24.score.f1, kMinF1) << name << " (conventional_d24)";
        }
    }

    // Two boxes (one partly hiding the other), a sphere and a ground slab, all scaled by
    // `scale` and moved by `offset`; the camera looks at them from a 3/4 view.
    void build_scene(const glm::dvec3& offset = glm::dvec3(0.0), double scale = 1.0) {
        const auto box = add_mesh("box", geo::box(glm::vec3(0.5f)));
        const auto slab = add_mesh("slab", geo::box(glm::vec3(6.0f, 0.1f, 6.0f)));
        const auto ball = add_mesh("ball", geo::uv_sphere(0.6f, 16, 32));
        const glm::dmat4 place =
            glm::scale(glm::translate(glm::dmat4(1.0), offset), glm::dvec3(scale));
        add_item(slab, place * glm::translate(glm::dmat4(1.0), {0.0, -0.1, 0.0}));
        add_item(box, place * glm::translate(glm::dmat4(1.0), {0.0, 0.5, 0.0}));
        add_item(box, place * glm::translate(glm::dmat4(1.0), {0.6, 0.5, -1.6}));
        add_item(ball, place * glm::translate(glm::dmat4(1.0), {-1.4, 0.6, -0.8}));
        frame.camera.eye = offset + glm::dvec3(3.5, 2.5, 5.0) * scale;
        frame.camera.target = offset + glm::dvec3(0.0, 0.4, -0.5) * scale;
        frame.camera.fov_y_deg = 45.0;
        frame.camera.near = 0.1 * scale;
        frame.camera.far = 100.0 * scale;
    }
};

TEST_F(StabilityTest, NearFarRatios) {
    build_scene();
    // Seen from 60 units with a narrow lens: depth precision is spent by distance, not by
    // what the picture shows.
    frame.camera.eye =
        frame.camera.target + glm::normalize(frame.camera.eye - frame.camera.target) * 60.0;
    frame.camera.fov_y_deg = 7.0;
    struct Planes {
        double near, far;
        bool d24_passes;
    };
    // 24-bit fixed-point depth runs out of precision as near shrinks: the default format
    // (reversed-Z float) keeps a constant relative precision at every depth.
    for (const Planes p :
         {Planes{1.0, 100.0, true}, Planes{0.1, 1e3, true}, Planes{1e-2, 1e4, true},
          Planes{1e-3, 1e5, true}, Planes{1e-4, 1e6, false}}) {
        frame.camera.near = p.near;
        frame.camera.far = p.far;
        char name[64];
        std::snprintf(name, sizeof name, "near %g far %g", p.near, p.far);
        expect_stable(name, p.d24_passes);
    }
}

TEST_F(StabilityTest, FarFromTheOrigin) {
    for (const double d : {0.0, 1e5, 1e6}) {
        reset_scene();
        build_scene(glm::dvec3(d, 0.5 * d, -d));
        char name[64];
        std::snprintf(name, sizeof name, "translated %g", d);
        expect_stable(name);
    }
}

TEST_F(StabilityTest, TinyAndHugeScales) {
    for (const double s : {1e-4, 1.0, 1e4}) {
        reset_scene();
        build_scene(glm::dvec3(0.0), s);
        char name[64];
        std::snprintf(name, sizeof name, "scale %g", s);
        expect_stable(name);
    }
}

TEST_F(StabilityTest, EdgesThroughTheNearPlaneAndBehindTheCamera) {
    // The camera stands inside a row of boxes and over a slab that runs far behind it: edges
    // cross the near plane, and some boxes lie wholly or partly behind the eye.
    const auto box = add_mesh("box", geo::box(glm::vec3(0.5f)));
    const auto slab = add_mesh("slab", geo::box(glm::vec3(1.5f, 0.1f, 40.0f)));
    add_item(slab, glm::translate(glm::dmat4(1.0), {0.0, -0.1, 0.0}));
    for (int i = -6; i <= 6; ++i) {
        add_item(box, glm::translate(glm::dmat4(1.0), {1.2, 0.5, 3.0 * i + 0.4}));
        add_item(box, glm::translate(glm::dmat4(1.0), {-1.2, 0.5, 3.0 * i - 0.7}));
    }
    frame.camera.eye = {0.3, 0.7, 0.35};
    frame.camera.target = {0.1, 0.5, -5.0};
    frame.camera.fov_y_deg = 80.0;
    frame.camera.near = 0.2;
    frame.camera.far = 200.0;
    settings.frustum_culling = false;  // let the geometry shader see what lies behind the eye
    expect_stable("near plane and behind");
}

TEST_F(StabilityTest, GrazingSilhouettes) {
    // A box seen exactly face-on (its sides are edge-on), a thin plate seen from almost in its
    // plane, and a finely tessellated sphere whose silhouette faces graze the view.
    const auto box = add_mesh("box", geo::box(glm::vec3(0.5f)));
    const auto plate = add_mesh("plate", geo::box(glm::vec3(2.0f, 0.01f, 2.0f)));
    const auto ball = add_mesh("ball", geo::uv_sphere(0.7f, 48, 96));
    add_item(box, glm::translate(glm::dmat4(1.0), {-1.2, 0.0, 0.0}));
    add_item(plate, glm::translate(glm::dmat4(1.0), {0.0, -0.45, -1.0}));
    add_item(ball, glm::translate(glm::dmat4(1.0), {1.3, 0.2, -0.5}));
    frame.camera.eye = {-1.2, -0.44, 6.0};  // the plate's top is at y = -0.44: grazing
    frame.camera.target = {-1.2, -0.44, 0.0};
    frame.camera.fov_y_deg = 50.0;
    frame.camera.near = 0.1;
    frame.camera.far = 100.0;
    expect_stable("grazing");
}

// A unit box whose faces are fans of `n` slivers each, all coplanar within a face.
geo::TriMesh sliver_box(int n) {
    geo::TriMesh m;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = -1; side <= 1; side += 2) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            auto corner = [&](float a, float b) {
                glm::vec3 p(0.0f);
                p[axis] = 0.5f * static_cast<float>(side);
                p[u] = a;
                p[v] = b;
                return p;
            };
            // Fan from corner (-,-) to points along the far edges (+, t) and (t, +).
            const auto base = static_cast<std::uint32_t>(m.positions.size());
            m.positions.push_back(corner(-0.5f, -0.5f));
            for (int i = 0; i <= n; ++i)
                m.positions.push_back(
                    corner(0.5f, -0.5f + static_cast<float>(i) / static_cast<float>(n)));
            for (int i = n - 1; i >= 0; --i)
                m.positions.push_back(
                    corner(-0.5f + static_cast<float>(i) / static_cast<float>(n), 0.5f));
            for (std::uint32_t i = 1; i < static_cast<std::uint32_t>(2 * n + 1); ++i) {
                // Winding so the face points along +axis * side.
                if (side > 0)
                    m.indices.insert(m.indices.end(), {base, base + i, base + i + 1});
                else
                    m.indices.insert(m.indices.end(), {base, base + i + 1, base + i});
            }
        }
    }
    return m;
}

TEST_F(StabilityTest, SliversAndLongThinTriangles) {
    // Faces made of 1:400 slivers must draw like plain faces (no lines inside them), and a
    // 200-unit beam of 1:10000 triangles must draw its four long edges.
    const auto slivers = add_mesh("slivers", sliver_box(400));
    const auto beam = add_mesh("beam", geo::box(glm::vec3(100.0f, 0.01f, 0.01f)));
    add_item(slivers, glm::translate(glm::dmat4(1.0), {0.0, 0.5, 0.0}));
    add_item(beam, glm::translate(glm::dmat4(1.0), {0.0, 1.4, -2.0}));
    frame.camera.eye = {2.0, 2.0, 3.0};
    frame.camera.target = {0.0, 0.6, 0.0};
    frame.camera.fov_y_deg = 50.0;
    frame.camera.near = 0.1;
    frame.camera.far = 500.0;
    expect_stable("slivers and long triangles");
}

// Two 4-unit quads hinged on the z axis, the angle between their normals `deg`.
geo::TriMesh hinge(double deg) {
    const double a = glm::radians(deg);
    geo::TriMesh m;
    const auto c = static_cast<float>(-4.0 * std::cos(a)),
               s = static_cast<float>(4.0 * std::sin(a));
    m.positions = {{0, 0, -2}, {0, 0, 2}, {4, 0, -2}, {4, 0, 2}, {c, s, -2}, {c, s, 2}};
    m.indices = {0, 1, 2, 2, 1, 3, 0, 4, 1, 1, 4, 5};
    return m;
}

TEST_F(StabilityTest, CreaseAngleThresholdIsResolved) {
    // At the 60 degree threshold +-1e-4 degrees: float32 still resolves it (cos changes by
    // 1.5e-6, 25 ulps at 0.5), so the GPU must put the hinge on the same side as the double
    // reference: a crease above the threshold, none below.
    frame.camera.eye = {1.0, 6.0, 1.5};
    frame.camera.target = {0.5, 0.0, 0.0};
    frame.camera.fov_y_deg = 60.0;
    frame.camera.near = 0.1;
    frame.camera.far = 100.0;
    std::size_t lit[2] = {0, 0};
    int k = 0;
    for (const double deg : {60.0 + 1e-4, 60.0 - 1e-4}) {
        reset_scene();
        add_item(add_mesh("hinge", hinge(deg)));
        const Outcome o =
            check(k == 0 ? "hinge 60+1e-4 deg" : "hinge 60-1e-4 deg", DepthFormat::reversed_f32);
        EXPECT_TRUE(o.finite);
        EXPECT_EQ(o.score.f1, 1.0) << deg;
        lit[k++] = o.score.ref_lit;
    }
    EXPECT_GT(lit[0], lit[1] + 50) << "the crease above the threshold must add its line";
}

}  // namespace
