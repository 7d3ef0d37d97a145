// The exact CPU reference's material lines (ReferenceInstance::material_lines): an analytic
// cube whose top has another material than its sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"
#include "geometry/reference/reference.h"

namespace bz::geo {
namespace {

constexpr int kMaterialW = 320, kMaterialH = 240;

ReferenceView material_view() {
    ReferenceView v;
    v.width = kMaterialW;
    v.height = kMaterialH;
    v.fov_y_deg = 50.0;
    return v;
}

AdjacencyMesh two_material_box_lines() {
    TriMesh m = box(glm::vec3(1.0f));
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        m.face_materials.push_back(glm::cross(b - a, c - a).y > 0.0f ? 1u : 0u);
    }
    return build_line_mesh(m);
}

// Window position (OpenGL's: origin bottom-left) of a world point seen through `mv`.
glm::dvec2 project(const glm::dmat4& mv, glm::dvec3 p) {
    const glm::dvec3 q = glm::dvec3(mv * glm::dvec4(p, 1.0));
    const double f = 1.0 / std::tan(glm::radians(material_view().fov_y_deg) * 0.5);
    const double aspect = static_cast<double>(kMaterialW) / kMaterialH;
    const glm::dvec2 ndc(f / aspect * q.x / -q.z, f * q.y / -q.z);
    return (ndc + 1.0) * 0.5 * glm::dvec2(kMaterialW, kMaterialH);
}

// Distance from point p to the segment a-b.
double distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 d = b - a;
    const double t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p - (a + d * t));
}

TEST(ReferenceMaterialLines, ExactlyTheTopsEdgesThatAreNoSilhouette) {
    const AdjacencyMesh mesh = two_material_box_lines();
    ReferenceInstance inst;
    inst.mesh = &mesh;
    inst.model_view = glm::lookAt(glm::dvec3(2.6, 3.4, 4.2), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    inst.cos_crease = -1.0;  // no creases
    // The top's edges against +x (x = 1) and +z (z = 1): both faces in view, so no
    // silhouette; the top's other two edges are silhouettes.
    const glm::dvec2 ex0 = project(inst.model_view, {1, 1, -1}),
                     ex1 = project(inst.model_view, {1, 1, 1}),
                     ez0 = project(inst.model_view, {-1, 1, 1});
    for (const bool on : {false, true}) {
        inst.material_lines = on;
        const std::vector<VisibleSegment> segs = reference_segments({&inst, 1}, material_view());
        double length[2] = {0.0, 0.0};  // along the x = 1 and the z = 1 edge
        int silhouettes = 0;
        for (const VisibleSegment& s : segs) {
            if (s.kind == LineKind::silhouette) ++silhouettes;
            if (s.kind != LineKind::material) continue;
            EXPECT_TRUE(on) << "a material line with material lines off";
            const bool on_x = distance(s.a, ex0, ex1) < 1e-6 && distance(s.b, ex0, ex1) < 1e-6;
            const bool on_z = distance(s.a, ex1, ez0) < 1e-6 && distance(s.b, ex1, ez0) < 1e-6;
            ASSERT_TRUE(on_x || on_z) << "material line off the top's front edges";
            length[on_x ? 0 : 1] += glm::length(s.b - s.a);
        }
        EXPECT_EQ(silhouettes, 6);
        EXPECT_NEAR(length[0], on ? glm::length(ex1 - ex0) : 0.0, 1e-6);
        EXPECT_NEAR(length[1], on ? glm::length(ez0 - ex1) : 0.0, 1e-6);
    }
}

TEST(ReferenceMaterialLines, NonePastTheCreasesDistanceLod) {
    // cos_crease below -1 is the renderer's "no creases at all" for a tiny object: no material
    // lines either, as the shaders do.
    const AdjacencyMesh mesh = two_material_box_lines();
    ReferenceInstance inst;
    inst.mesh = &mesh;
    inst.model_view = glm::lookAt(glm::dvec3(2.6, 3.4, 4.2), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    inst.cos_crease = -2.0;
    inst.material_lines = true;
    for (const VisibleSegment& s : reference_segments({&inst, 1}, material_view()))
        EXPECT_NE(s.kind, LineKind::material);
}

}  // namespace
}  // namespace bz::geo
