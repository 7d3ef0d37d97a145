// Culling before per-edge work (render/lines/edge_culling.h) on analytic scenes where the
// answer is known: it must keep every edge that is a feature (the shader's own tests, done
// here in double) and drop most of the rest.
#include "render/lines/edge_culling.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/derived/edge_list.h"
#include "geometry/generated/primitives.h"
#include "geometry/generated/subdivide.h"
#include "geometry/line_mesh/line_mesh.h"

namespace bz::render {
namespace {

struct EdgeScene {
    geo::AdjacencyMesh mesh;
    geo::ClusteredEdges clusters;
    explicit EdgeScene(const geo::TriMesh& m) : EdgeScene(geo::build_line_mesh(m)) {}
    explicit EdgeScene(geo::AdjacencyMesh m)
        : mesh(std::move(m)), clusters(geo::cluster_edges(mesh, geo::build_edge_list(mesh))) {}
};

CullView view_of(float fov_deg = 60.0f) {
    CullView v;
    v.proj = glm::perspective(glm::radians(fov_deg), 4.0f / 3.0f, 0.1f, 1000.0f);
    v.near = 0.1f;
    v.far = 1000.0f;
    return v;
}

// What edges.comp does with an edge, in double in view space: a feature edge (silhouette,
// crease below cos_crease, or boundary), with skip_back_faces as the shader applies it.
bool is_feature(const geo::AdjacencyMesh& m, const geo::MeshEdge& e, const glm::dmat4& mv,
                double cos_crease, bool skip_back_faces) {
    const auto view = [&](std::uint32_t v) {
        return glm::dvec3(mv * glm::dvec4(glm::dvec3(m.positions[v]), 1.0));
    };
    const glm::dvec3 a = view(e.a), b = view(e.b);
    const auto front = [&](const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& o) {
        return glm::dot(glm::cross(q - p, o - p), -p) > 0.0;
    };
    const bool front_a = front(a, b, view(e.opp_a));
    if (e.opp_b == geo::kNoVertex) return front_a || !skip_back_faces;
    const bool front_b = front(a, view(e.opp_b), b);
    if (front_a != front_b) return true;
    if (!front_a && skip_back_faces) return false;
    return e.cos_dihedral < cos_crease;
}

struct CulledEdges {
    std::vector<bool> dispatched;  // per edge of the clustered list
    EdgeCullStats stats;
};

CulledEdges cull_edges(const EdgeScene& s, const glm::mat4& mv, float cos_crease,
                       bool skip_back_faces, const CullView& v = view_of()) {
    CulledEdges out;
    std::vector<EdgeWorkItem> work;
    append_edge_work(s.clusters, mv, cos_crease, skip_back_faces, v, 7u, work, out.stats);
    out.dispatched.assign(s.clusters.edges.size(), false);
    for (const EdgeWorkItem& w : work) {
        EXPECT_EQ(w.x, 7u);
        EXPECT_LE(w.z, geo::kMaxClusterEdges);
        for (std::uint32_t i = w.y; i < w.y + w.z; ++i) out.dispatched[i] = true;
    }
    return out;
}

// The same with the CPU prefilter (edge_prefilter.h): the edges it lists, one entry each.
CulledEdges list_edges(const EdgeScene& s, const glm::mat4& mv, float cos_crease,
                       bool skip_back_faces, const CullView& v = view_of()) {
    const EdgeFacingTable table =
        build_edge_facing_table(s.mesh, s.clusters, geo::face_normals(s.mesh));
    CulledEdges out;
    std::vector<EdgeWorkItem> work;
    append_edge_work(s.clusters, mv, cos_crease, skip_back_faces, v, 7u, work, out.stats,
                     {.prefilter = &table});
    out.dispatched.assign(s.clusters.edges.size(), false);
    for (const EdgeWorkItem& w : work) {
        EXPECT_EQ(w.x, 7u);
        EXPECT_LT(w.y, s.clusters.edges.size());
        EXPECT_FALSE(out.dispatched[w.y]) << "edge " << w.y << " listed twice";
        out.dispatched[w.y] = true;
    }
    EXPECT_EQ(work.size(), out.stats.edges_dispatched);
    return out;
}

// Every feature edge is dispatched; returns how many feature edges there are.
std::size_t expect_features_kept(const EdgeScene& s, const glm::mat4& mv, float cos_crease,
                                 bool skip_back_faces, const CulledEdges& c) {
    std::size_t features = 0;
    for (std::size_t i = 0; i < s.clusters.edges.size(); ++i) {
        if (!is_feature(s.mesh, s.clusters.edges[i], glm::dmat4(mv), cos_crease, skip_back_faces))
            continue;
        ++features;
        EXPECT_TRUE(c.dispatched[i]) << "feature edge " << s.clusters.edges[i].id << " culled";
    }
    return features;
}

TEST(EdgeCulling, ASpheresSilhouetteIsKeptAndMostOfItsEdgesAreNotTested) {
    const EdgeScene s(geo::uv_sphere(1.0f, 96, 192));
    for (const glm::vec3 eye : {glm::vec3(0, 0, 4), glm::vec3(3, 2, 1), glm::vec3(0, 5, 0.01f),
                                glm::vec3(-1.3f, -1.1f, 0.9f)}) {
        const glm::mat4 mv = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
        for (const bool skip : {true, false}) {
            const CulledEdges c = cull_edges(s, mv, -2.0f, skip);
            const std::size_t silhouette = expect_features_kept(s, mv, -2.0f, skip, c);
            // One silhouette loop: at least one ring's worth of edges, far fewer than all.
            EXPECT_GE(silhouette, 96u);
            EXPECT_LT(c.stats.edges_dispatched * 4, s.clusters.edges.size())
                << "eye " << eye.x << "," << eye.y << "," << eye.z << " skip " << skip;
            EXPECT_GE(c.stats.edges_dispatched, silhouette);
        }
    }
}

TEST(EdgeCulling, AMirroredInstanceKeepsItsSilhouetteToo) {
    const EdgeScene s(geo::uv_sphere(1.0f, 48, 96));
    const glm::mat4 mv = glm::lookAt(glm::vec3(2, 1, 3), glm::vec3(0.0f), glm::vec3(0, 1, 0)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 2.0f));
    const CulledEdges c = cull_edges(s, mv, -2.0f, false);
    EXPECT_GE(expect_features_kept(s, mv, -2.0f, false, c), 48u);
    EXPECT_LT(c.stats.edges_dispatched * 3, s.clusters.edges.size());
}

TEST(EdgeCulling, CreasesOfAOneWayClusterAreStillTested) {
    // A box far off: every cluster faces one way, but its 90 degree creases are features.
    const EdgeScene s(geo::box(glm::vec3(1.0f)));
    const glm::mat4 mv = glm::lookAt(glm::vec3(4, 3, 5), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const CulledEdges c = cull_edges(s, mv, 0.5f, true);
    EXPECT_EQ(expect_features_kept(s, mv, 0.5f, true, c), 9u);  // 6 silhouette + 3 front creases
}

TEST(EdgeCulling, FlatSubdivisionAddsNoEdgeToTest) {
    // A box split 4^3 times over: 12 creases of 8 pieces each; the rest lie between coplanar
    // faces and are never tested, from any view.
    const EdgeScene s(geo::subdivide_flat(geo::build_line_mesh(geo::box(glm::vec3(1.0f))), 3));
    for (const glm::vec3 eye :
         {glm::vec3(4, 3, 5), glm::vec3(0.2f, 6, 0.1f), glm::vec3(-3, -2, 4)}) {
        const glm::mat4 mv = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
        for (const bool skip : {true, false}) {
            const CulledEdges c = cull_edges(s, mv, 0.5f, skip);
            EXPECT_GT(expect_features_kept(s, mv, 0.5f, skip, c), 0u);
            EXPECT_LE(c.stats.edges_dispatched, 12u * 8u);
        }
    }
}

TEST(EdgeCulling, AThinOpenSheetKeepsItsBoundaryFromBothSides) {
    const EdgeScene s(
        geo::grid(40, 40, 0.1f, 40));  // 4 units, open: both sides drawn, never skipped
    for (const float y : {3.0f, -3.0f}) {
        const glm::mat4 mv =
            glm::lookAt(glm::vec3(0.5f, y, 2.0f), glm::vec3(0.0f), glm::vec3(0, 0, -1));
        const CulledEdges c = cull_edges(s, mv, -2.0f, false);
        const std::size_t features = expect_features_kept(s, mv, -2.0f, false, c);
        EXPECT_EQ(features, 160u);  // the rim: 4 x 40 boundary edges, nothing else
        // A flat sheet faces one way from anywhere: only the rim is tested.
        EXPECT_EQ(c.stats.edges_dispatched, features);
    }
}

TEST(EdgeCulling, ClustersBeyondTheGuardBandAreDroppedAndTheEdgeOnesKept) {
    // A strip 200 units long across the view: the guard band clips to twice the frustum, so
    // a cluster is dropped only when every edge of it lies beyond one of its planes.
    const EdgeScene s(geo::grid(200, 4, 1.0f, 200));
    const CullView v = view_of(40.0f);
    const glm::mat4 mv = glm::lookAt(glm::vec3(0, 30, 30), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const CulledEdges c = cull_edges(s, mv, -2.0f, false, v);
    EXPECT_GT(c.stats.outside_frustum, 0u);
    EXPECT_LT(c.stats.outside_frustum, c.stats.clusters);
    // Every edge of a dropped cluster is outside one guard plane at both ends.
    const glm::dmat4 pmv = glm::dmat4(v.proj) * glm::dmat4(mv);
    for (std::size_t i = 0; i < s.clusters.edges.size(); ++i) {
        if (c.dispatched[i]) continue;
        const geo::MeshEdge& e = s.clusters.edges[i];
        if (s.clusters.crease_keys[i] == geo::kAlwaysFeatureKey) {
            const glm::dvec4 pa = pmv * glm::dvec4(glm::dvec3(s.mesh.positions[e.a]), 1.0);
            const glm::dvec4 pb = pmv * glm::dvec4(glm::dvec3(s.mesh.positions[e.b]), 1.0);
            const bool beyond =
                (pa.x > 2 * pa.w && pb.x > 2 * pb.w) || (pa.x < -2 * pa.w && pb.x < -2 * pb.w) ||
                (pa.y > 2 * pa.w && pb.y > 2 * pb.w) || (pa.y < -2 * pa.w && pb.y < -2 * pb.w) ||
                (pa.w < 0.1 && pb.w < 0.1);
            EXPECT_TRUE(beyond) << "boundary edge " << e.id << " dropped inside the guard band";
        }
    }
}

// Cluster groups (geo::EdgeClusterGroup) settle many of a sphere's clusters at once; what
// they skip, the clusters' own tests would have skipped or found no feature in.
TEST(EdgeCulling, GroupsSettleManyClustersAtOnceAndKeepEveryFeature) {
    EdgeScene s(geo::uv_sphere(1.0f, 192, 384));
    for (const glm::vec3 eye :
         {glm::vec3(0, 0, 4), glm::vec3(3, 2, 1), glm::vec3(0.2f, 0.1f, 30)}) {
        const glm::mat4 mv = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
        for (const bool skip : {true, false}) {
            SCOPED_TRACE(std::to_string(eye.z) + (skip ? " skipping back faces" : ""));
            const CulledEdges grouped = cull_edges(s, mv, -2.0f, skip);
            // Over two fifths of the 230 groups, from every view (a third to nearly all).
            EXPECT_GT(grouped.stats.groups_settled * 5, s.clusters.groups.size() * 2)
                << s.clusters.groups.size() << " groups";
            expect_features_kept(s, mv, -2.0f, skip, grouped);
            EdgeScene ungrouped = s;
            ungrouped.clusters.groups.clear();
            const CulledEdges alone = cull_edges(ungrouped, mv, -2.0f, skip);
            EXPECT_EQ(alone.stats.groups_settled, 0u);
            EXPECT_EQ(grouped.stats.clusters, alone.stats.clusters);
            EXPECT_LE(grouped.stats.edges_dispatched, alone.stats.edges_dispatched);
            for (std::size_t i = 0; i < grouped.dispatched.size(); ++i)
                EXPECT_TRUE(!grouped.dispatched[i] || alone.dispatched[i]) << "edge " << i;
        }
    }
    // The sphere behind the eye: every group is outside the view.
    const glm::mat4 away = glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0, 0, 8), glm::vec3(0, 1, 0));
    const CulledEdges c = cull_edges(s, away, -2.0f, true);
    EXPECT_EQ(c.stats.groups_settled, s.clusters.groups.size());
    EXPECT_EQ(c.stats.edges_dispatched, 0u);
}

// The CPU prefilter may only ever list more than edges.comp draws: every feature edge (the
// shader's tests in double, above) is listed, from views chosen to put faces near grazing,
// and it lists little besides.
TEST(EdgePrefilter, ListsEverySpheresSilhouetteEdgeAndLittleElse) {
    const EdgeScene s(geo::uv_sphere(1.0f, 96, 192));
    for (const glm::vec3 eye : {glm::vec3(0, 0, 4), glm::vec3(3, 2, 1), glm::vec3(0, 5, 0.01f),
                                glm::vec3(-1.3f, -1.1f, 0.9f), glm::vec3(0, 1.05f, 0)}) {
        // (Nearer the surface the float eye - vertex of the shader, and of the prefilter,
        // loses digits the double reference here keeps: edge_prefilter_test.cpp compares the
        // prefilter with the shader itself there.) A wide view, so that from 1.05 the whole
        // silhouette lies inside the guard band.
        const glm::mat4 mv = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 0.6f, 0.8f));
        const CullView wide = view_of(150.0f);
        for (const bool skip : {true, false}) {
            const std::string where = "eye " + std::to_string(eye.x) + "," + std::to_string(eye.y) +
                                      "," + std::to_string(eye.z) +
                                      (skip ? " skipping back faces" : "");
            SCOPED_TRACE(where);
            const CulledEdges clusters = cull_edges(s, mv, -2.0f, skip, wide);
            const CulledEdges c = list_edges(s, mv, -2.0f, skip, wide);
            const std::size_t silhouette = expect_features_kept(s, mv, -2.0f, skip, c);
            EXPECT_EQ(c.stats.edges_prefiltered, clusters.stats.edges_dispatched) << where;
            // Only the edges near the silhouette are unsure: a few times the loop at most.
            EXPECT_LE(c.stats.edges_dispatched, 3 * silhouette + 16) << where;
            EXPECT_LT(c.stats.edges_dispatched * 4, clusters.stats.edges_dispatched) << where;
        }
    }
}

TEST(EdgePrefilter, AMirroredAndStretchedInstanceKeepsItsSilhouette) {
    const EdgeScene s(geo::uv_sphere(1.0f, 48, 96));
    const glm::mat4 mv = glm::lookAt(glm::vec3(2, 1, 3), glm::vec3(0.0f), glm::vec3(0, 1, 0)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 2.0f));
    const CulledEdges c = list_edges(s, mv, -2.0f, false);
    EXPECT_GE(expect_features_kept(s, mv, -2.0f, false, c), 48u);
}

TEST(EdgePrefilter, CreasesAndTheRimOfAnOpenSheetAreListedFromBothSidesAndEdgeOn) {
    const EdgeScene box(geo::subdivide_flat(geo::build_line_mesh(geo::box(glm::vec3(1.0f))), 2));
    const glm::mat4 corner = glm::lookAt(glm::vec3(4, 3, 5), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    for (const bool skip : {true, false}) {
        const CulledEdges c = list_edges(box, corner, 0.5f, skip);
        EXPECT_GT(expect_features_kept(box, corner, 0.5f, skip, c), 0u);
    }
    const EdgeScene sheet(geo::grid(40, 40, 0.1f, 40));
    // Above, below, and with the eye in the sheet's plane, where every face is a tie that the
    // shader decides in view space: then everything is listed.
    for (const glm::vec3 eye :
         {glm::vec3(0.5f, 3, 2), glm::vec3(0.5f, -3, 2), glm::vec3(0, 0, 5)}) {
        const glm::mat4 mv = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0.01f));
        const CulledEdges clusters = cull_edges(sheet, mv, -2.0f, false);
        const CulledEdges c = list_edges(sheet, mv, -2.0f, false);
        expect_features_kept(sheet, mv, -2.0f, false, c);
        if (eye.y == 0.0f)
            EXPECT_EQ(c.stats.edges_dispatched, clusters.stats.edges_dispatched) << "edge-on";
        else
            EXPECT_EQ(c.stats.edges_dispatched, 160u) << "the rim alone";
    }
}

TEST(EdgePrefilter, ListedEntriesNameTheirClustersBoundsRecordAndFirstEdge) {
    const EdgeScene s(geo::uv_sphere(1.0f, 48, 96));
    const glm::mat4 mv = glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const EdgeFacingTable table =
        build_edge_facing_table(s.mesh, s.clusters, geo::face_normals(s.mesh));
    const HizView hiz(view_of().proj, 0.1f, 640, 480);
    std::vector<EdgeWorkItem> work;
    std::vector<HizBounds> bounds;
    EdgeCullStats stats;
    append_edge_work(s.clusters, mv, -2.0f, true, view_of(), 3u, work, stats,
                     {.hiz = &hiz, .bounds = &bounds, .prefilter = &table});
    ASSERT_FALSE(work.empty());
    EXPECT_EQ(bounds.size(), stats.items);  // one record per cluster with a listed edge
    std::size_t firsts = 0;
    for (std::size_t i = 0; i < work.size(); ++i) {
        EXPECT_LT(work[i].z, bounds.size());
        const bool first = i == 0 || work[i].z != work[i - 1].z;
        EXPECT_EQ(work[i].w, first ? 1u : 0u) << "entry " << i;
        firsts += first;
    }
    EXPECT_EQ(firsts, bounds.size());
}

TEST(EdgeCulling, ObjectSpaceEyeAndSign) {
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, -5)) *
                         glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, -1.0f, 1.0f));
    const glm::vec4 e = object_space_eye(mv);
    const glm::vec4 back = mv * glm::vec4(glm::vec3(e), 1.0f);
    EXPECT_NEAR(glm::length(glm::vec3(back)), 0.0f, 1e-5f);
    EXPECT_EQ(e.w, -1.0f);
    EXPECT_EQ(object_space_eye(glm::mat4(0.0f)).w, 0.0f);
}

}  // namespace
}  // namespace bz::render
