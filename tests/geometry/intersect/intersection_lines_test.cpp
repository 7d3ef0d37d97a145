// Intersection lines (geometry/intersect/): analytic scenes whose crossings are known exactly.
#include "geometry/intersect/intersection_lines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

#include "geometry/generated/primitives.h"
#include "geometry/intersect/triangle_crossing.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::geo {
namespace {

glm::dmat4 moved_to(glm::dvec3 p) {
    return glm::translate(glm::dmat4(1.0), p);
}

double total_length(const std::vector<IntersectionSegment>& segs) {
    double sum = 0.0;
    for (const IntersectionSegment& s : segs) sum += glm::length(s.b - s.a);
    return sum;
}

// Each end of a closed loop of segments meets exactly one other end (rounded to 1e-7).
bool forms_closed_loops(const std::vector<IntersectionSegment>& segs) {
    std::map<std::tuple<long long, long long, long long>, int> ends;
    auto key = [](glm::dvec3 p) {
        return std::make_tuple(std::llround(p.x * 1e7), std::llround(p.y * 1e7),
                               std::llround(p.z * 1e7));
    };
    for (const IntersectionSegment& s : segs) {
        ++ends[key(s.a)];
        ++ends[key(s.b)];
    }
    for (const auto& [k, n] : ends)
        if (n != 2) return false;
    return !segs.empty();
}

TEST(TriangleCrossing, TwoTrianglesThroughEachOther) {
    const Triangle3 t{glm::dvec3(-1, 0, -1), glm::dvec3(1, 0, -1), glm::dvec3(0, 0, 1)};
    const Triangle3 u{glm::dvec3(0, -1, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 2)};
    const auto c = triangle_crossing(t, u);
    ASSERT_TRUE(c);
    // On x = 0, y = 0: from z = 0 (u's edge) to z = 1 (t's apex).
    EXPECT_NEAR(std::min(c->a.z, c->b.z), 0.0, 1e-12);
    EXPECT_NEAR(std::max(c->a.z, c->b.z), 1.0, 1e-12);
    EXPECT_NEAR(c->a.x, 0.0, 1e-12);
    EXPECT_NEAR(c->a.y, 0.0, 1e-12);
}

TEST(TriangleCrossing, CoplanarTouchingAndSharedEdgesGiveNone) {
    const Triangle3 t{glm::dvec3(0, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0)};  // faces +y
    // Coplanar and overlapping.
    EXPECT_FALSE(triangle_crossing(
        t, {glm::dvec3(0.2, 0, 0.2), glm::dvec3(2, 0, 0.2), glm::dvec3(0.2, 0, 2)}));
    // Sharing the edge (0,0,0)-(1,0,0), folded up and folded down.
    EXPECT_FALSE(
        triangle_crossing(t, {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 0), glm::dvec3(0.5, 1, 0.3)}));
    EXPECT_FALSE(
        triangle_crossing(t, {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 0), glm::dvec3(0.5, -1, 0.3)}));
    // Sharing a vertex only.
    EXPECT_FALSE(
        triangle_crossing(t, {glm::dvec3(0, 0, 0), glm::dvec3(-1, 1, 0), glm::dvec3(-1, -1, -1)}));
    // Resting on it: an edge on its plane, the rest above.
    EXPECT_FALSE(triangle_crossing(
        t, {glm::dvec3(0.1, 0, 0.1), glm::dvec3(0.6, 0, 0.1), glm::dvec3(0.3, 1, 0.1)}));
    // Degenerate.
    EXPECT_FALSE(triangle_crossing(
        t, {glm::dvec3(0.2, -1, 0.2), glm::dvec3(0.2, 1, 0.2), glm::dvec3(0.2, 0, 0.2)}));
}

TEST(IntersectionLines, BoxSunkIntoGroundCutsItsFootprint) {
    // Grid cells of 1 put the box's walls (x, z = +-1) exactly on ground triangle edges: the
    // triangles on both sides of such an edge touch the wall; exactly one reports it.
    const AdjacencyMesh ground = build_line_mesh(grid(6, 6, 1.0f, 2));
    const AdjacencyMesh cube = build_line_mesh(box(glm::vec3(1.0f)));
    for (const double shift : {0.0, 0.37}) {
        const PlacedMesh g = place_mesh(ground, moved_to({shift, 0.0, shift}));
        const PlacedMesh b = place_mesh(cube, moved_to({0.0, 0.4, 0.0}));
        const std::vector<IntersectionSegment> segs = pair_intersections(g, b);
        EXPECT_NEAR(total_length(segs), 8.0, 1e-9) << "shift " << shift;
        EXPECT_TRUE(forms_closed_loops(segs));
        for (const IntersectionSegment& s : segs) {
            for (const glm::dvec3 p : {s.a, s.b}) {
                EXPECT_NEAR(p.y, 0.0, 1e-12);
                EXPECT_NEAR(std::max(std::abs(p.x), std::abs(p.z)), 1.0, 1e-12);
            }
        }
        // The same, asked the other way round.
        EXPECT_NEAR(total_length(pair_intersections(b, g)), 8.0, 1e-9);
    }
}

TEST(IntersectionLines, TwoBoxesCrossAlongTheKnownPolygon) {
    // A bar 1 x 1 x 4 through the side of a 2 x 2 x 2 box: it enters the box's +x face along
    // y = +-0.5 and cuts the z = +-1 faces along a U (x = 0.5 and y = +-0.5, x in [0.5, 1]).
    const AdjacencyMesh cube = build_line_mesh(box(glm::vec3(1.0f)));
    const AdjacencyMesh bar = build_line_mesh(box(glm::vec3(0.5f, 0.5f, 2.0f)));
    const PlacedMesh a = place_mesh(cube, glm::dmat4(1.0));
    const PlacedMesh b = place_mesh(bar, moved_to({1.0, 0.1, 0.0}));
    const std::vector<IntersectionSegment> segs = pair_intersections(a, b);
    EXPECT_NEAR(total_length(segs), 2 * 2.0 + 2 * (0.5 + 0.5 + 1.0), 1e-9);
    for (const IntersectionSegment& s : segs) {
        for (const glm::dvec3 p : {s.a, s.b}) {
            const bool on_x_face =
                std::abs(p.x - 1.0) < 1e-12 && std::abs(std::abs(p.y - 0.1) - 0.5) < 1e-12;
            const bool on_z_face =
                std::abs(std::abs(p.z) - 1.0) < 1e-12 &&
                ((std::abs(p.x - 0.5) < 1e-12 && std::abs(p.y - 0.1) <= 0.5 + 1e-12) ||
                 (std::abs(std::abs(p.y - 0.1) - 0.5) < 1e-12 && p.x >= 0.5 - 1e-12));
            EXPECT_TRUE(on_x_face || on_z_face) << p.x << " " << p.y << " " << p.z;
        }
    }
}

TEST(IntersectionLines, SphereThroughPlaneIsACircle) {
    const AdjacencyMesh sphere = build_line_mesh(uv_sphere(1.0f, 24, 48));
    const AdjacencyMesh ground = build_line_mesh(grid(4, 4, 1.0f, 4));
    const PlacedMesh s = place_mesh(sphere, moved_to({0.2, -0.3, 0.1}));
    const PlacedMesh g = place_mesh(ground, glm::dmat4(1.0));
    const std::vector<IntersectionSegment> segs = pair_intersections(s, g);
    const double r = std::sqrt(1.0 - 0.3 * 0.3);
    ASSERT_TRUE(forms_closed_loops(segs));
    // The facets' chords lie within 1 - cos(pi / 24) of the sphere.
    const double inner = r - (1.0 - std::cos(3.14159265358979 / 24.0)) / r;
    for (const IntersectionSegment& x : segs) {
        for (const glm::dvec3 p : {x.a, x.b}) {
            EXPECT_NEAR(p.y, 0.0, 1e-12);
            const double d = glm::length(glm::dvec2(p.x - 0.2, p.z - 0.1));
            EXPECT_LE(d, r + 1e-9);
            EXPECT_GE(d, inner - 1e-9);
        }
    }
    EXPECT_NEAR(total_length(segs), 2.0 * 3.14159265358979 * r, 0.02 * r);
}

TEST(IntersectionLines, AMeshsOwnNeighboursAndCoplanarOverlapGiveNone) {
    for (const TriMesh& m : {box(glm::vec3(1.0f)), uv_sphere(1.0f, 12, 24), fin(),
                             cylinder(0.5f, 1.0f, 16), grid(3, 3, 1.0f, 1)}) {
        const AdjacencyMesh mesh = build_line_mesh(m);
        EXPECT_TRUE(self_intersections(place_mesh(mesh, glm::dmat4(1.0))).empty());
    }
    // Two grounds, one half a cell off the other, in the same plane; a box resting on one.
    const AdjacencyMesh ground = build_line_mesh(grid(4, 4, 1.0f, 2));
    const AdjacencyMesh cube = build_line_mesh(box(glm::vec3(1.0f)));
    const PlacedMesh g = place_mesh(ground, glm::dmat4(1.0));
    EXPECT_TRUE(pair_intersections(g, place_mesh(ground, moved_to({0.5, 0.0, 0.5}))).empty());
    EXPECT_TRUE(pair_intersections(g, place_mesh(cube, moved_to({0.3, 1.0, 0.2}))).empty());
}

TEST(IntersectionLines, AFoldedMeshCrossesItself) {
    // Two boxes in one mesh (as an imported file may hold parts that pass through each
    // other): their crossing is the mesh's own intersection line.
    TriMesh two = box(glm::vec3(1.0f));
    const TriMesh other = box(glm::vec3(0.5f, 0.5f, 2.0f));
    const auto base = static_cast<std::uint32_t>(two.positions.size());
    for (const glm::vec3& p : other.positions)
        two.positions.push_back(p + glm::vec3(1.0f, 0.1f, 0.0f));
    for (const std::uint32_t i : other.indices) two.indices.push_back(base + i);
    const AdjacencyMesh mesh = build_line_mesh(two);
    const std::vector<IntersectionSegment> segs =
        self_intersections(place_mesh(mesh, glm::dmat4(1.0)));
    EXPECT_NEAR(total_length(segs), 8.0, 1e-6);
    for (const IntersectionSegment& s : segs) EXPECT_LT(s.triangle_a, s.triangle_b);
}

TEST(IntersectionLines, SceneListsEachPairWhoseBoundsMeet) {
    const AdjacencyMesh ground = build_line_mesh(grid(8, 8, 1.0f, 4));
    const AdjacencyMesh cube = build_line_mesh(box(glm::vec3(0.5f)));
    std::vector<PlacedMesh> scene;
    scene.push_back(place_mesh(ground, glm::dmat4(1.0)));
    scene.push_back(place_mesh(cube, moved_to({-2.0, 0.2, 0.0})));  // sunk: a 4-unit square
    scene.push_back(place_mesh(cube, moved_to({2.0, 0.6, 0.0})));   // floating: none
    scene.push_back(place_mesh(cube, moved_to({-2.3, 0.9, 0.4})));  // through the first cube
    const std::vector<SceneIntersection> all = scene_intersections(scene);
    double with_ground = 0.0;
    bool cubes = false;
    for (const SceneIntersection& x : all) {
        EXPECT_LT(x.first, x.second);
        EXPECT_NE(x.second, 2u);
        if (x.first == 0) with_ground += glm::length(x.segment.b - x.segment.a);
        if (x.first == 1 && x.second == 3) cubes = true;
    }
    EXPECT_NEAR(with_ground, 4.0, 1e-9);
    EXPECT_TRUE(cubes);
}

}  // namespace
}  // namespace bz::geo
