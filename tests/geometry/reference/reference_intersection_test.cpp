// The exact reference's intersection lines (ReferenceOptions::intersection_lines): a box sunk
// into a ground plane, whose ground line is a square, seen from above and in front.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"
#include "geometry/reference/reference.h"

namespace bz::geo {
namespace {

constexpr int kXsectW = 320, kXsectH = 240;

ReferenceView xsect_view() {
    ReferenceView v;
    v.width = kXsectW;
    v.height = kXsectH;
    v.fov_y_deg = 50.0;
    return v;
}

glm::dvec2 xsect_project(const glm::dmat4& view, glm::dvec3 p) {
    const glm::dvec3 q = glm::dvec3(view * glm::dvec4(p, 1.0));
    const double f = 1.0 / std::tan(glm::radians(xsect_view().fov_y_deg) * 0.5);
    const double aspect = static_cast<double>(kXsectW) / kXsectH;
    const glm::dvec2 ndc(f / aspect * q.x / -q.z, f * q.y / -q.z);
    return (ndc + 1.0) * 0.5 * glm::dvec2(kXsectW, kXsectH);
}

double xsect_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 d = b - a;
    const double t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p - (a + d * t));
}

struct SunkBox {
    AdjacencyMesh ground = build_line_mesh(grid(8, 8, 1.0f, 4));
    AdjacencyMesh cube = build_line_mesh(box(glm::vec3(1.0f)));
    glm::dmat4 view = glm::lookAt(glm::dvec3(3.5, 3.0, 6.0), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    std::vector<ReferenceInstance> instances() const {
        ReferenceInstance g{&ground, view};
        ReferenceInstance b{&cube, view * glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0.3, 0))};
        return {g, b};
    }
};

// The smallest distance from window point p to a segment of `kind`.
double nearest_of_kind(const std::vector<VisibleSegment>& segs, LineKind kind, glm::dvec2 p) {
    double best = 1e30;
    for (const VisibleSegment& s : segs)
        if (s.kind == kind) best = std::min(best, xsect_distance(p, s.a, s.b));
    return best;
}

TEST(ReferenceIntersectionLines, TheGroundLineInFrontShowsTheOneBehindTheBoxDoesNot) {
    const SunkBox scene;
    ReferenceOptions o;
    o.intersection_lines = true;
    const std::vector<VisibleSegment> segs = reference_segments(scene.instances(), xsect_view(), o);
    // The square's front side (z = 1) and its +x side lie on surfaces that face the eye:
    // visible, though both surfaces they lie on pass through them.
    for (const double x : {-0.8, -0.3, 0.0, 0.4, 0.9})
        EXPECT_LT(
            nearest_of_kind(segs, LineKind::intersection, xsect_project(scene.view, {x, 0, 1})),
            1e-6)
            << x;
    for (const double z : {-0.8, 0.0, 0.8})
        EXPECT_LT(
            nearest_of_kind(segs, LineKind::intersection, xsect_project(scene.view, {1, 0, z})),
            1e-6);
    // The back (z = -1) and -x sides are behind the box.
    for (const double t : {-0.5, 0.0, 0.5}) {
        EXPECT_GT(
            nearest_of_kind(segs, LineKind::intersection, xsect_project(scene.view, {t, 0, -1})),
            1.0);
        EXPECT_GT(
            nearest_of_kind(segs, LineKind::intersection, xsect_project(scene.view, {-1, 0, t})),
            1.0);
    }
    for (const VisibleSegment& s : segs) {
        if (s.kind == LineKind::intersection) {
            EXPECT_EQ(s.instance, 0u);  // the ground's
        }
    }
}

TEST(ReferenceIntersectionLines, OffByDefaultAndOnlyBetweenOccluders) {
    const SunkBox scene;
    for (const VisibleSegment& s : reference_segments(scene.instances(), xsect_view()))
        EXPECT_NE(s.kind, LineKind::intersection);
    std::vector<ReferenceInstance> inst = scene.instances();
    inst[1].occluder = false;
    ReferenceOptions o;
    o.intersection_lines = true;
    for (const VisibleSegment& s : reference_segments(inst, xsect_view(), o))
        EXPECT_NE(s.kind, LineKind::intersection);
}

TEST(ReferenceIntersectionLines, AnotherObjectInFrontHidesThem) {
    const SunkBox scene;
    std::vector<ReferenceInstance> inst = scene.instances();
    // A wall between the eye and the box's front: hides the front side of the square.
    const AdjacencyMesh wall = build_line_mesh(box(glm::vec3(3.0f, 2.0f, 0.05f)));
    inst.push_back({&wall, scene.view * glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1.0, 2.5))});
    ReferenceOptions o;
    o.intersection_lines = true;
    const std::vector<VisibleSegment> segs = reference_segments(inst, xsect_view(), o);
    EXPECT_GT(nearest_of_kind(segs, LineKind::intersection, xsect_project(scene.view, {0, 0, 1})),
              1.0);
    // Its own crossing with the ground is there, in front of everything.
    EXPECT_LT(
        nearest_of_kind(segs, LineKind::intersection, xsect_project(scene.view, {0, 0, 2.55})),
        1e-6);
}

}  // namespace
}  // namespace bz::geo
