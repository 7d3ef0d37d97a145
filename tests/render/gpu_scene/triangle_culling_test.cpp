// Culling triangle clusters before the prepass (render/gpu_scene/triangle_culling.h) on
// analytic scenes: every triangle that could reach the picture is drawn, and most of what
// cannot is not.
#include "render/gpu_scene/triangle_culling.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::render {
namespace {

constexpr float kNear = 0.1f, kFar = 1000.0f;

glm::mat4 projection(float fov_deg = 60.0f) {
    return glm::perspective(glm::radians(fov_deg), 4.0f / 3.0f, kNear, kFar);
}

struct TriangleScene {
    geo::AdjacencyMesh mesh;
    geo::ClusteredTriangles clusters;
    explicit TriangleScene(const geo::TriMesh& m)
        : mesh(geo::build_line_mesh(m)), clusters(geo::cluster_triangles(mesh)) {}
};

struct CulledTriangles {
    std::vector<bool> drawn;  // per triangle of the clustered list
    TriangleCullStats stats;
};

CulledTriangles cull_triangles(const TriangleScene& s, const glm::mat4& mv, bool skip_back_faces,
                               const glm::mat4& proj = projection()) {
    CulledTriangles out;
    std::vector<TriangleDraw> draws;
    const ViewVolume view(proj, kNear, kFar, 1.0);
    append_triangle_draws(s.clusters.clusters, s.clusters.all, mv, skip_back_faces, view, 5u, draws,
                          out.stats);
    out.drawn.assign(s.clusters.indices.size() / 3, false);
    for (const TriangleDraw& d : draws) {
        EXPECT_EQ(d.base_instance, 5u);
        EXPECT_EQ(d.instance_count, 1u);
        EXPECT_EQ(d.first_index % 3, 0u);
        for (std::uint32_t i = d.first_index; i < d.first_index + d.count; i += 3)
            out.drawn[i / 3] = true;
    }
    return out;
}

// The triangle's corners in clip space.
std::array<glm::dvec4, 3> clip_corners(const TriangleScene& s, std::size_t t,
                                       const glm::dmat4& pmv) {
    std::array<glm::dvec4, 3> out;
    for (int i = 0; i < 3; ++i)
        out[i] = pmv * glm::dvec4(glm::dvec3(s.mesh.positions[s.clusters.indices[3 * t + i]]), 1.0);
    return out;
}

// Whether every corner lies beyond one clip plane: then the triangle is clipped away whole.
bool clipped_whole(const std::array<glm::dvec4, 3>& c) {
    const auto all = [&](auto beyond) { return beyond(c[0]) && beyond(c[1]) && beyond(c[2]); };
    return all([](const glm::dvec4& p) { return p.x > p.w; }) ||
           all([](const glm::dvec4& p) { return p.x < -p.w; }) ||
           all([](const glm::dvec4& p) { return p.y > p.w; }) ||
           all([](const glm::dvec4& p) { return p.y < -p.w; }) ||
           all([](const glm::dvec4& p) { return p.z > p.w; }) ||
           all([](const glm::dvec4& p) { return p.z < -p.w; });
}

// Whether the triangle's view-space normal faces away from the eye (what back-face culling
// removes, exactly when it is back-facing on screen).
bool faces_away(const TriangleScene& s, std::size_t t, const glm::dmat4& mv) {
    glm::dvec3 p[3];
    for (int i = 0; i < 3; ++i)
        p[i] = glm::dvec3(
            mv * glm::dvec4(glm::dvec3(s.mesh.positions[s.clusters.indices[3 * t + i]]), 1.0));
    return glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), -p[0]) <= 0.0;
}

// Every triangle the GPU would rasterise is drawn; returns how many that is.
std::size_t expect_visible_drawn(const TriangleScene& s, const glm::mat4& mv, bool skip_back_faces,
                                 const CulledTriangles& c, const glm::mat4& proj = projection()) {
    const glm::dmat4 pmv = glm::dmat4(proj) * glm::dmat4(mv);
    std::size_t visible = 0;
    for (std::size_t t = 0; t < c.drawn.size(); ++t) {
        if (clipped_whole(clip_corners(s, t, pmv))) continue;
        if (skip_back_faces && faces_away(s, t, glm::dmat4(mv))) continue;
        ++visible;
        EXPECT_TRUE(c.drawn[t]) << "triangle " << t << " culled but on screen";
    }
    return visible;
}

TEST(TriangleCulling, AClosedSphereDrawsItsFrontAndSkipsMostOfItsBack) {
    const TriangleScene s(geo::uv_sphere(1.0f, 96, 192));
    for (const glm::vec3 eye : {glm::vec3(0, 0, 4), glm::vec3(3, 2, 1), glm::vec3(0, 5, 0.01f),
                                glm::vec3(-1.3f, -1.1f, 0.9f)}) {
        const glm::mat4 mv = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
        const CulledTriangles c = cull_triangles(s, mv, true);
        const std::size_t visible = expect_visible_drawn(s, mv, true, c);
        EXPECT_GT(visible, 0u);
        // About half a sphere faces away; at least a third of all triangles are skipped.
        EXPECT_LT(c.stats.triangles_drawn * 3, c.stats.triangles * 2)
            << "eye " << eye.x << "," << eye.y << "," << eye.z;
        EXPECT_GT(c.stats.facing_away, 0u);
    }
}

TEST(TriangleCulling, WithoutBackFaceCullingEveryClusterInViewIsDrawn) {
    const TriangleScene s(geo::uv_sphere(1.0f, 48, 96));
    const glm::mat4 mv = glm::lookAt(glm::vec3(0, 1, 4), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const CulledTriangles c = cull_triangles(s, mv, false);
    EXPECT_EQ(c.stats.triangles_drawn, c.stats.triangles);
    EXPECT_EQ(c.stats.facing_away, 0u);
}

TEST(TriangleCulling, AMirroredInstanceKeepsWhatItsScreenWindingShows) {
    const TriangleScene s(geo::uv_sphere(1.0f, 48, 96));
    const glm::mat4 mv = glm::lookAt(glm::vec3(2, 1, 3), glm::vec3(0.0f), glm::vec3(0, 1, 0)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 2.0f));
    const CulledTriangles c = cull_triangles(s, mv, true);
    EXPECT_GT(expect_visible_drawn(s, mv, true, c), 0u);
    EXPECT_LT(c.stats.triangles_drawn, c.stats.triangles);
}

TEST(TriangleCulling, AThinOpenSheetIsDrawnFromBothSides) {
    const TriangleScene s(geo::grid(40, 40, 0.1f, 40));  // open: back faces are never culled
    for (const float y : {3.0f, -3.0f}) {
        const glm::mat4 mv =
            glm::lookAt(glm::vec3(0.5f, y, 2.0f), glm::vec3(0.0f), glm::vec3(0, 0, -1));
        const CulledTriangles c = cull_triangles(s, mv, false);
        EXPECT_GT(expect_visible_drawn(s, mv, false, c), c.stats.triangles / 2);
        EXPECT_EQ(c.stats.facing_away, 0u);
    }
}

TEST(TriangleCulling, ClustersOutsideTheViewAreDroppedAndTheEdgeOnesKept) {
    // A strip 200 units long across the view: clusters beyond the frustum's sides are dropped,
    // those across its edge are kept.
    const TriangleScene s(geo::grid(200, 4, 1.0f, 200));
    const glm::mat4 proj = projection(40.0f);
    const glm::mat4 mv = glm::lookAt(glm::vec3(0, 30, 30), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const CulledTriangles c = cull_triangles(s, mv, false, proj);
    EXPECT_GT(c.stats.outside_frustum, 0u);
    EXPECT_LT(c.stats.outside_frustum, c.stats.clusters);
    EXPECT_GT(expect_visible_drawn(s, mv, false, c, proj), 0u);
}

TEST(TriangleCulling, AClusterBehindTheEyeOrBeyondFarIsDropped) {
    const TriangleScene s(geo::uv_sphere(1.0f, 16, 32));
    for (const float z : {5.0f, -2000.0f}) {  // behind the eye; beyond the far plane
        const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, z));
        const CulledTriangles c = cull_triangles(s, mv, true);
        EXPECT_EQ(c.stats.triangles_drawn, 0u);
        EXPECT_EQ(c.stats.outside_frustum, c.stats.clusters);
    }
}

TEST(TriangleCulling, KeptNeighboursMergeIntoOneDraw) {
    const TriangleScene s(geo::uv_sphere(1.0f, 48, 96));
    std::vector<TriangleDraw> draws;
    TriangleCullStats stats;
    const ViewVolume view(projection(), kNear, kFar, 1.0);
    const glm::mat4 mv = glm::lookAt(glm::vec3(0, 0, 6), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    append_triangle_draws(s.clusters.clusters, s.clusters.all, mv, false, view, 0u, draws, stats);
    ASSERT_EQ(draws.size(), 1u);  // everything in view, nothing skipped: one run
    EXPECT_EQ(draws[0].count, s.clusters.indices.size());
}

}  // namespace
}  // namespace bz::render
