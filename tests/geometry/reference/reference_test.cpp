// The exact CPU reference: analytic scenes whose visible edges are known, its building blocks
// (clipping, the crossing rule, the BVH) against brute force, and its edge rules at the crease
// threshold.
#include "geometry/reference/reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "geometry/generated/primitives.h"
#include "geometry/generated/subdivide.h"
#include "geometry/line_mesh/line_mesh.h"
#include "geometry/reference/reference_bvh.h"
#include "geometry/reference/reference_edges.h"
#include "geometry/reference/reference_raster.h"

namespace bz::geo {
namespace {

using Segments = std::vector<std::pair<glm::dvec3, glm::dvec3>>;

constexpr int kW = 320, kH = 240;

ReferenceView view(double near = 0.1, double far = 100.0) {
    ReferenceView v;
    v.width = kW;
    v.height = kH;
    v.fov_y_deg = 50.0;
    v.near = near;
    v.far = far;
    return v;
}

glm::dmat4 look(glm::dvec3 eye, glm::dvec3 target = glm::dvec3(0.0)) {
    return glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0));
}

// Marks whole segments (world space, seen through `view_m`) with the reference's own clipping
// and crossing rule: what the mask must be when exactly these edges are visible.
std::vector<std::uint8_t> expected(const Segments& segs, const glm::dmat4& view_m,
                                   const ReferenceView& v) {
    std::vector<std::uint8_t> m(static_cast<std::size_t>(kW * kH), 0);
    const auto p = detail::Projection::of(v);
    for (const auto& [a, b] : segs) {
        const auto c = detail::clip_edge(glm::dvec3(view_m * glm::dvec4(a, 1.0)),
                                         glm::dvec3(view_m * glm::dvec4(b, 1.0)), p);
        if (c) detail::mark_segment(m, kW, kH, c->sa, c->sb);
    }
    return m;
}

std::size_t lit(const std::vector<std::uint8_t>& m) {
    return static_cast<std::size_t>(
        std::count_if(m.begin(), m.end(), [](auto x) { return x != 0; }));
}

// The 12 edges of a cube of half size h, split into those seen from the (+,+,+) octant and
// the three that meet at the hidden corner.
void cube_edges(double h, Segments& visible, Segments& hidden) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int s1 = -1; s1 <= 1; s1 += 2) {
            for (int s2 = -1; s2 <= 1; s2 += 2) {
                glm::dvec3 a(0.0), b(0.0);
                const int u = (axis + 1) % 3, w = (axis + 2) % 3;
                a[axis] = -h;
                b[axis] = h;
                a[u] = b[u] = s1 * h;
                a[w] = b[w] = s2 * h;
                (s1 < 0 && s2 < 0 ? hidden : visible).push_back({a, b});
            }
        }
    }
}

TEST(Reference, CubeShowsExactlyItsNineVisibleEdges) {
    const AdjacencyMesh cube = build_line_mesh(box({1, 1, 1}));
    const glm::dmat4 v = look({3.0, 2.5, 4.0});
    const ReferenceInstance inst{&cube, v, 0.5, true};
    ReferenceStats stats;
    const auto mask = reference_mask({&inst, 1}, view(), {}, &stats);
    Segments vis, hid;
    cube_edges(1.0, vis, hid);
    EXPECT_EQ(mask, expected(vis, v, view()));
    EXPECT_EQ(stats.feature_edges, 12u);
    EXPECT_GT(lit(mask), 500u);

    // Without occlusion (the arcade style) the three hidden edges show too.
    ReferenceOptions arcade;
    arcade.occlusion = false;
    Segments all = vis;
    all.insert(all.end(), hid.begin(), hid.end());
    EXPECT_EQ(reference_mask({&inst, 1}, view(), arcade), expected(all, v, view()));
}

TEST(Reference, ObjectBehindAnotherLeavesNoTrace) {
    const AdjacencyMesh big = build_line_mesh(box({2, 2, 2}));
    const AdjacencyMesh small = build_line_mesh(box({0.5, 0.5, 0.5}));
    const glm::dmat4 v = look({0.0, 0.0, 10.0});
    const ReferenceInstance front{&big, v, 0.5, true};
    const ReferenceInstance behind{&small, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, -5.0}),
                                   0.5, true};
    const ReferenceInstance both[] = {front, behind};
    EXPECT_EQ(reference_mask(both, view()), reference_mask({&front, 1}, view()));
    // A non-occluder in front hides nothing but shows itself.
    const ReferenceInstance ghost{&small, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, 4.0}), 0.5,
                                  false};
    const ReferenceInstance with_ghost[] = {front, ghost};
    const auto m = reference_mask(with_ghost, view());
    const auto f = reference_mask({&front, 1}, view());
    for (std::size_t i = 0; i < m.size(); ++i)
        ASSERT_GE(m[i], f[i]) << "pixel " << i << " lost behind a non-occluder";
    EXPECT_GT(lit(m), lit(f));
}

TEST(Reference, PartlyHiddenEdgeIsCutWhereTheOccluderEnds) {
    // A long horizontal bar behind a square: the bar's lines must stop at the square's sides.
    const AdjacencyMesh bar = build_line_mesh(box({3.0, 0.1, 0.1}));
    const AdjacencyMesh wall = build_line_mesh(box({1.0, 1.0, 0.05}));
    const glm::dmat4 v = look({0.0, 0.0, 10.0});
    const ReferenceInstance insts[] = {
        {&bar, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, -1.0}), 0.5, true},
        {&wall, v, 0.5, true}};
    const auto m = reference_mask(insts, view());
    // Window x of the wall's sides: no bar pixels strictly between them except the wall's own.
    const auto p = detail::Projection::of(view());
    const double left = p.window(p.clip(glm::dvec3(v * glm::dvec4(-1.0, 0.0, 0.05, 1.0)))).x;
    const double right = p.window(p.clip(glm::dvec3(v * glm::dvec4(1.0, 0.0, 0.05, 1.0)))).x;
    const int row = kH / 2;  // the bar's centre line is hidden; its top and bottom edges too
    for (int x = static_cast<int>(left) + 2; x < static_cast<int>(right) - 2; ++x) {
        for (int y = row - 3; y <= row + 3; ++y) {
            EXPECT_EQ(m[static_cast<std::size_t>(y * kW + x)], 0) << x << "," << y;
        }
    }
    // Outside the wall the bar's edges do show.
    int outside = 0;
    for (int y = row - 3; y <= row + 3; ++y)
        outside += m[static_cast<std::size_t>(y * kW + static_cast<int>(left) - 10)] ? 1 : 0;
    EXPECT_GE(outside, 2);
}

TEST(Reference, NearPlaneClipsAndBehindTheCameraIsEmpty) {
    const AdjacencyMesh cube = build_line_mesh(box({1, 1, 1}));
    // Behind the camera: nothing at all.
    const glm::dmat4 v = look({0.0, 0.0, 5.0});
    const ReferenceInstance behind{&cube, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, 10.0}),
                                   0.5, true};
    EXPECT_EQ(lit(reference_mask({&behind, 1}, view())), 0u);
    // Straddling the near plane: the edges crossing it are clipped, not wrapped around.
    // (The cube spans view depths 1 to 3; the near plane at 1.5 cuts its four side edges.)
    const ReferenceInstance straddle{&cube, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, 3.0}),
                                     0.5, true};
    const auto m = reference_mask({&straddle, 1}, view(1.5, 100.0));
    EXPECT_GT(lit(m), 0u);
    ReferenceOptions arcade;
    arcade.occlusion = false;
    Segments vis, hid;
    cube_edges(1.0, vis, hid);
    vis.insert(vis.end(), hid.begin(), hid.end());
    EXPECT_EQ(
        reference_mask({&straddle, 1}, view(1.5, 100.0), arcade),
        expected(vis, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, 3.0}), view(1.5, 100.0)));
    // Seen from inside the cut-open box every edge left is visible, so occlusion changes
    // nothing.
    EXPECT_EQ(m, reference_mask({&straddle, 1}, view(1.5, 100.0), arcade));
}

TEST(Reference, SubdividedMeshDrawsTheSameImage) {
    const AdjacencyMesh cube = build_line_mesh(box({1, 1, 1}));
    const AdjacencyMesh fine = subdivide_flat(cube, 2);
    EXPECT_EQ(fine.triangle_count(), cube.triangle_count() * 16);
    const glm::dmat4 v = look({3.0, 2.5, 4.0});
    const ReferenceInstance a{&cube, v, 0.5, true}, b{&fine, v, 0.5, true};
    EXPECT_EQ(reference_mask({&a, 1}, view()), reference_mask({&b, 1}, view()));
    EXPECT_THROW(subdivide_flat(cube, 7), std::invalid_argument);
}

TEST(Reference, RejectsBadInput) {
    const AdjacencyMesh cube = build_line_mesh(box({1, 1, 1}));
    const ReferenceInstance inst{&cube, glm::dmat4(1.0), 0.5, true};
    ReferenceView v = view();
    v.width = 0;
    EXPECT_THROW(reference_mask({&inst, 1}, v), std::invalid_argument);
    v = view(1.0, 0.5);
    EXPECT_THROW(reference_mask({&inst, 1}, v), std::invalid_argument);
    const ReferenceInstance null_mesh{};
    EXPECT_THROW(reference_mask({&null_mesh, 1}, view()), std::invalid_argument);
}

// Two unit quads hinged on the z axis with a given angle between their normals.
AdjacencyMesh hinge(double dihedral_deg) {
    const double a = glm::radians(dihedral_deg);
    TriMesh m;
    m.positions = {{0, 0, 0},
                   {0, 0, 1},
                   {1, 0, 0},
                   {1, 0, 1},
                   {static_cast<float>(-std::cos(a)), static_cast<float>(std::sin(a)), 0.0f},
                   {static_cast<float>(-std::cos(a)), static_cast<float>(std::sin(a)), 1.0f}};
    // Quad 1 in y = 0 facing +y; quad 2 turned up by `a` about the z axis, sharing edge 0-1.
    m.indices = {0, 1, 2, 2, 1, 3, 0, 4, 1, 1, 4, 5};
    return build_line_mesh(m);
}

std::size_t creases(const AdjacencyMesh& mesh, double cos_crease) {
    const ReferenceInstance inst{&mesh, look({0.3, 5.0, 0.5}, {0.0, 0.0, 0.5}), cos_crease, true};
    std::vector<glm::dvec3> vp;
    for (const auto& p : mesh.positions)
        vp.push_back(glm::dvec3(inst.model_view * glm::dvec4(glm::dvec3(p), 1.0)));
    std::vector<detail::FeatureEdge> edges;
    detail::find_feature_edges(inst, 0, vp, edges);
    return static_cast<std::size_t>(std::count_if(
        edges.begin(), edges.end(),
        [](const detail::FeatureEdge& e) { return e.kind == detail::FeatureKind::crease; }));
}

TEST(Reference, CreaseThresholdIsResolvedInDouble) {
    const double c = std::cos(glm::radians(60.0));
    // Normals 60 + 1e-4 degrees apart: a crease; 60 - 1e-4: not.
    EXPECT_EQ(creases(hinge(60.0 + 1e-4), c), 1u);
    EXPECT_EQ(creases(hinge(60.0 - 1e-4), c), 0u);
    EXPECT_EQ(creases(hinge(90.0), c), 1u);
    EXPECT_EQ(creases(hinge(10.0), c), 0u);
}

TEST(ReferenceRaster, CrossingMarksMatchBruteForce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(-20.0, 80.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng));
        std::vector<std::uint8_t> fast(64 * 48, 0), brute(64 * 48, 0);
        detail::mark_segment(fast, 64, 48, a, b);
        for (int y = 0; y < 48; ++y) {
            for (int x = 0; x < 64; ++x) {
                if (detail::crosses_pixel({x + 0.5, y + 0.5}, a, b))
                    brute[static_cast<std::size_t>((47 - y) * 64 + x)] = 255;
            }
        }
        ASSERT_EQ(fast, brute) << "segment " << i;
    }
}

TEST(ReferenceRaster, PerspectiveCorrectPointsProjectOntoTheSpine) {
    const auto p = detail::Projection::of(view());
    const auto e = detail::clip_edge({-3.0, 1.0, -2.0}, {4.0, -2.0, -30.0}, p);
    ASSERT_TRUE(e);
    for (double u : {0.0, 0.1, 0.5, 0.77, 1.0}) {
        const glm::dvec2 s = p.window(p.clip(e->at(u)));
        const glm::dvec2 want = e->sa + (e->sb - e->sa) * u;
        EXPECT_NEAR(s.x, want.x, 1e-9);
        EXPECT_NEAR(s.y, want.y, 1e-9);
    }
    // Entirely beyond the lateral guard band (x > 2w): clipped away.
    EXPECT_FALSE(detail::clip_edge({100.0, 0.0, -2.0}, {120.0, 0.0, -3.0}, p));
}

TEST(ReferenceBvh, AnswersLikeBruteForce) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-10.0, 10.0), small(-1.5, 1.5);
    std::vector<detail::BvhTriangle> tris;
    for (std::uint32_t i = 0; i < 400; ++i) {
        const glm::dvec3 c(u(rng), u(rng), u(rng) - 20.0);
        tris.push_back({c + glm::dvec3(small(rng), small(rng), small(rng)),
                        c + glm::dvec3(small(rng), small(rng), small(rng)),
                        c + glm::dvec3(small(rng), small(rng), small(rng)), i % 3, 3 * i, 3 * i + 1,
                        3 * i + 2});
    }
    const detail::TriangleBvh bvh(tris);
    EXPECT_EQ(bvh.size(), tris.size());
    int hits = 0;
    for (int q = 0; q < 2000; ++q) {
        const glm::dvec3 end(u(rng), u(rng), u(rng) - 20.0);
        const detail::ExcludedEdge ex{static_cast<std::uint32_t>(q % 3),
                                      static_cast<std::uint32_t>(q),
                                      static_cast<std::uint32_t>(q + 1),
                                      {}};
        bool brute = false;
        for (const auto& t : tris) {
            const bool own = t.instance == ex.instance &&
                             (t.v0 == ex.va || t.v1 == ex.va || t.v2 == ex.va) &&
                             (t.v0 == ex.vb || t.v1 == ex.vb || t.v2 == ex.vb);
            const double h = detail::intersect(t, glm::dvec3(0.0), end);
            if (!own && h >= 0.05 && h <= 0.95) brute = true;
        }
        ASSERT_EQ(bvh.any_hit(glm::dvec3(0.0), end, 0.05, 0.95, ex), brute) << "query " << q;
        hits += brute ? 1 : 0;
    }
    EXPECT_GT(hits, 50);  // the scene is dense enough to test both answers
    EXPECT_LT(hits, 1950);
}

}  // namespace
}  // namespace bz::geo

namespace bz::geo {
namespace {

TEST(ReferenceSegments, CrossExactlyTheMasksPixelsAndSplitWhereHidden) {
    // The bar behind the wall: its long edges split in two at the wall's sides.
    const AdjacencyMesh bar = build_line_mesh(box({3.0, 0.1, 0.1}));
    const AdjacencyMesh wall = build_line_mesh(box({1.0, 1.0, 0.05}));
    const glm::dmat4 v = look({0.0, 0.0, 10.0});
    const ReferenceInstance insts[] = {
        {&bar, v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, -1.0}), 0.5, true},
        {&wall, v, 0.5, true}};
    ReferenceStats stats;
    const std::vector<VisibleSegment> segs = reference_segments(insts, view(), {}, &stats);
    std::vector<std::uint8_t> m(static_cast<std::size_t>(kW * kH), 0);
    const std::size_t marked = mark_segments(segs, kW, kH, m);
    EXPECT_EQ(marked, lit(m));
    EXPECT_EQ(m, reference_mask(insts, view()));
    std::size_t bar_pieces = 0, wall_pieces = 0;
    for (const VisibleSegment& s : segs) {
        // The wall's edges along the view axis project to points: dots, not pieces.
        if (glm::length(s.b - s.a) < 1e-9) continue;
        (s.instance == 0 ? bar_pieces : wall_pieces) += 1;
        EXPECT_TRUE(s.kind == LineKind::silhouette || s.kind == LineKind::crease);
    }
    EXPECT_EQ(wall_pieces, 4u);  // the wall's front square, whole
    // Seen head on, the bar's outline is its front face: the two long edges show in two pieces
    // each, one either side of the wall, and the two short end edges whole.
    EXPECT_EQ(bar_pieces, 6u);
    // No visible piece of the bar lies between the wall's sides on the wall's rows.
    const auto p = detail::Projection::of(view());
    const double left = p.window(p.clip(glm::dvec3(v * glm::dvec4(-1.0, 0.0, 0.05, 1.0)))).x;
    const double right = p.window(p.clip(glm::dvec3(v * glm::dvec4(1.0, 0.0, 0.05, 1.0)))).x;
    for (const VisibleSegment& s : segs) {
        if (s.instance != 0) continue;
        const double mid = 0.5 * (s.a.x + s.b.x);
        EXPECT_FALSE(mid > left + 1.0 && mid < right - 1.0) << s.a.x << " .. " << s.b.x;
    }
}

}  // namespace
}  // namespace bz::geo

namespace bz::geo {
namespace {

// A bar behind a cube behind a smaller cube, seen head on: the bar's front long edges are
// visible beyond the big cube, at level 1 behind it alone and level 2 behind both.
TEST(ReferenceSegments, OcclusionLevelsOfACubeBehindACubeBehindACube) {
    const AdjacencyMesh bar = build_line_mesh(box({3.0, 0.5, 1.0}));
    const AdjacencyMesh big = build_line_mesh(box({1.0, 1.0, 1.0}));
    const AdjacencyMesh small = build_line_mesh(box({0.3, 0.3, 0.3}));
    const glm::dmat4 v = look({0.0, 0.0, 10.0});
    auto at = [&](double z) { return v * glm::translate(glm::dmat4(1.0), {0.0, 0.0, z}); };
    const ReferenceInstance insts[] = {
        {&bar, at(-4.0), 0.5, true}, {&big, at(0.0), 0.5, true}, {&small, at(4.0), 0.5, true}};
    ReferenceOptions levels;
    levels.hidden_levels = 3;
    const std::vector<VisibleSegment> segs = reference_segments(insts, view(), levels);
    // With hidden levels the visible segments, and so the mask, are unchanged.
    std::vector<std::uint8_t> m(static_cast<std::size_t>(kW * kH), 0);
    mark_segments(segs, kW, kH, m);
    EXPECT_EQ(m, reference_mask(insts, view()));

    const auto p = detail::Projection::of(view());
    auto win = [&](glm::dvec3 w) { return p.window(p.clip(glm::dvec3(v * glm::dvec4(w, 1.0)))); };
    const double cx = kW * 0.5;
    const double big_half = win({1.0, 0.0, 1.0}).x - cx;    // the big cube's front face
    const double small_half = win({0.3, 0.0, 4.3}).x - cx;  // the small cube's front face
    const double top = win({0.0, 0.5, -3.0}).y;             // the bar's front face's top edge
    int pieces[3] = {0, 0, 0};
    for (const VisibleSegment& s : segs) {
        if (s.instance != 0 || std::abs(s.a.y - top) > 0.3 || std::abs(s.b.y - top) > 0.3) continue;
        if (std::abs(s.b.x - s.a.x) < 1.0) continue;
        const double mid = std::abs(0.5 * (s.a.x + s.b.x) - cx);
        const int want = mid < small_half ? 2 : (mid < big_half ? 1 : 0);
        EXPECT_EQ(s.level, want) << "segment " << s.a.x << " .. " << s.b.x;
        ASSERT_LE(s.level, 2);
        ++pieces[s.level];
        // Each piece ends at a cube's outline (or the bar's end), to within the bisection.
        for (const double x : {s.a.x, s.b.x}) {
            const double d = std::abs(x - cx);
            const double off = std::min({std::abs(d - small_half), std::abs(d - big_half),
                                         std::abs(d - (win({3.0, 0.5, -3.0}).x - cx))});
            EXPECT_LT(off, 0.05) << "end " << x;
        }
    }
    EXPECT_EQ(pieces[0], 2);  // left and right of the big cube
    EXPECT_EQ(pieces[1], 2);  // behind the big cube only, either side of the small one
    EXPECT_EQ(pieces[2], 1);  // behind both

    // Without hidden levels, no hidden segment is returned; with levels capped at 1, the
    // pieces behind both cubes are level 1.
    for (const VisibleSegment& s : reference_segments(insts, view())) EXPECT_EQ(s.level, 0);
    levels.hidden_levels = 1;
    for (const VisibleSegment& s : reference_segments(insts, view(), levels)) EXPECT_LE(s.level, 1);
    levels.hidden_levels = kMaxOcclusionLevel + 1;
    EXPECT_THROW(reference_segments(insts, view(), levels), std::invalid_argument);
}

}  // namespace
}  // namespace bz::geo
