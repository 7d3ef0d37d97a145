// Material boundaries as lines (RenderSettings::material_lines): both feature-line methods
// draw exactly the edges between faces of different materials, as the exact CPU reference
// does, on an analytic cube and on real multi-material models; off, they draw none.
#include <gtest/gtest.h>

#include <filesystem>

#include "geometry/generated/primitives.h"
#include "geometry/reference/mask_score.h"
#include "render/reference_frame.h"
#include "render/render_fixture.h"

using bz::render::LineMethod;
using bz::test::Mask;
using bz::test::RenderTest;

namespace {

using Segment = std::pair<glm::dvec3, glm::dvec3>;

// The unit cube whose top (+y) face has material 1 and every other face material 0.
bz::geo::TriMesh two_material_box() {
    bz::geo::TriMesh m = bz::geo::box(glm::vec3(1.0f));
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        m.face_materials.push_back(glm::cross(b - a, c - a).y > 0.0f ? 1u : 0u);
    }
    return m;
}

// Real models with faces of several materials that share edges (Debian's assimp-testmodels;
// found by importing every model there and keeping those with material boundaries): a cube
// with a material per face pair, one split along a face diagonal (OBJ); a LightWave scene of
// 3180 triangles with 340 boundary edges; and two whose boundaries all lie on creases or
// silhouettes from the framing view, so material lines add nothing there (the milk truck,
// glTF, 120 edges; a SIB model, 40), which both methods and the reference must agree on too.
struct MultiMaterialModel {
    const char* path;
    bool adds_lines;  // from the framing view, some boundary is no crease or silhouette
};
constexpr MultiMaterialModel kMultiMaterialModels[] = {
    {"/usr/share/assimp/models/OBJ/cube_usemtl.obj", true},
    {"/usr/share/assimp/models/LWO/LWO2/UglyVertexColors.lwo", true},
    {"/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", false},
    {"/usr/share/assimp/models/SIB/heffalump.sib", false},
};

}  // namespace

class MaterialLinesTest : public RenderTest {
  protected:
    Mask mask_with(LineMethod m, bool material_lines, const std::string& name) {
        settings.method = m;
        settings.material_lines = material_lines;
        compare_line_methods = false;
        return mask(name + (material_lines ? "_material_" : "_plain_") +
                    bz::render::line_method_name(m));
    }
    std::vector<std::uint8_t> reference(bool material_lines) {
        bz::render::ReferenceFrameOptions o;
        o.crease_angle_deg = settings.crease_angle_deg;
        o.material_lines = material_lines;
        return bz::render::reference_frame_mask(frame, meshes, kWidth, kHeight, o);
    }
};

TEST_F(MaterialLinesTest, CubeOfTwoMaterialsDrawsExactlyItsVisibleBoundaries) {
    add_item(add_mesh("two_material_box", two_material_box()));
    frame.camera.eye = {2.6, 3.4, 4.2};  // sees +x, +y and +z
    frame.camera.target = {0.0, 0.0, 0.0};
    settings = bz::render::preset("high");
    settings.crease_angle_deg = 180.0f;  // no creases: only silhouettes and material lines
    settings.lod = false;
    // The outline of the three faces in view, and the top's two edges against the +x and +z
    // faces (its other two are silhouettes already). Its diagonal and the +x/+z edge are not
    // lines.
    const std::vector<Segment> outline = {{{-1, 1, -1}, {-1, 1, 1}}, {{-1, 1, -1}, {1, 1, -1}},
                                          {{1, 1, -1}, {1, -1, -1}}, {{1, -1, -1}, {1, -1, 1}},
                                          {{1, -1, 1}, {-1, -1, 1}}, {{-1, -1, 1}, {-1, 1, 1}}};
    std::vector<Segment> with_material = outline;
    with_material.push_back({{1, 1, -1}, {1, 1, 1}});
    with_material.push_back({{1, 1, 1}, {-1, 1, 1}});
    for (const LineMethod m : bz::render::feature_line_methods()) {
        SCOPED_TRACE(bz::render::line_method_name(m));
        for (const bool on : {false, true}) {
            SCOPED_TRACE(on ? "material lines on" : "material lines off");
            const Mask got = mask_with(m, on, "material_cube");
            const Mask want = bz::test::expected_mask(frame.camera, kWidth, kHeight,
                                                      on ? with_material : outline);
            const bz::test::MaskScore s = bz::test::score_masks(got, want, 1);
            EXPECT_GE(s.precision, 0.99);
            EXPECT_GE(s.recall, 0.99);
            const double f1 =
                bz::geo::score_masks(got.pixels, reference(on), kWidth, kHeight, 1).f1;
            EXPECT_GE(f1, 0.99) << "F1 against the exact reference";
        }
    }
}

TEST_F(MaterialLinesTest, RealModelsAgreeWithTheReference) {
    for (const auto& [path, adds_lines] : kMultiMaterialModels) {
        SCOPED_TRACE(path);
        ASSERT_TRUE(std::filesystem::exists(path))
            << "install assimp-testmodels (tools/install-deps)";
        const bz::scene::MeshId id = show_model(path);
        ASSERT_TRUE(meshes.mesh(id).has_material_edges()) << "the model lost its materials";
        const std::string name = "material_" + std::filesystem::path(path).stem().string();
        settings = bz::render::preset("high");
        const std::vector<std::uint8_t> ref_on = reference(true), ref_off = reference(false);
        const auto lit = [](const std::vector<std::uint8_t>& m) {
            return std::count_if(m.begin(), m.end(), [](std::uint8_t v) { return v != 0; });
        };
        std::printf("%s: reference lit pixels, material lines on %td, off %td\n", name.c_str(),
                    lit(ref_on), lit(ref_off));
        if (adds_lines) {
            EXPECT_GT(lit(ref_on), lit(ref_off)) << "material lines add no pixel";
        } else {
            EXPECT_EQ(lit(ref_on), lit(ref_off));
        }
        for (const LineMethod m : bz::render::feature_line_methods()) {
            SCOPED_TRACE(bz::render::line_method_name(m));
            const Mask on = mask_with(m, true, name);
            const Mask off = mask_with(m, false, name);
            const double f1_on = bz::geo::score_masks(on.pixels, ref_on, kWidth, kHeight, 1).f1;
            const double f1_off = bz::geo::score_masks(off.pixels, ref_off, kWidth, kHeight, 1).f1;
            std::printf("%s %s: F1 material lines on %.4f, off %.4f\n", name.c_str(),
                        bz::render::line_method_name(m), f1_on, f1_off);
            EXPECT_GE(f1_on, 0.99);
            EXPECT_GE(f1_off, 0.99);
            if (adds_lines) {
                EXPECT_GT(on.count(), off.count());
            }
        }
    }
}
