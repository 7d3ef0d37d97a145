#pragma once
// A renderer on the shared headless context, plus helpers to render masks and save PNGs of
// what the tests look at (build/test-out/*.png).
#include <memory>
#include <string>

#include "geometry/line_mesh/line_mesh.h"
#include "render/mask_expect.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace bz::test {

// Real models nobody here made, from Debian's assimp-testmodels (tools/install-deps).
inline constexpr const char* kRealModels[] = {
    "/usr/share/assimp/models/PLY/Wuson.ply",
    "/usr/share/assimp/models/OBJ/spider.obj",
    "/usr/share/assimp/models/Collada/duck.dae",
    "/usr/share/assimp/models/glTF/CesiumMilkTruck/CesiumMilkTruck.gltf",
    "/usr/share/assimp/models/3DS/fels.3ds",
    "/usr/share/assimp/models/BLEND/Suzanne_248.blend",
};

// Two masks of the same frame by the two feature-line methods: the same lines, up to a few
// pixels where a face is seen exactly edge-on.
void expect_same_lines(const Mask& a, const Mask& b, const std::string& what);

class RenderTest : public GlTest {
  protected:
    static constexpr int kWidth = 320;
    static constexpr int kHeight = 240;

    void SetUp() override;
    scene::MeshId add_mesh(const std::string& name, const geo::TriMesh& mesh);
    void add_item(scene::MeshId id, const glm::dmat4& model = glm::dmat4(1.0));
    // Makes the model file at `path` the frame's only item, framed by a 50-degree camera.
    scene::MeshId show_model(const std::string& path);
    // The mask with settings' line method. For the feature-line methods it also renders the
    // mask with the other one and checks that both agree (see line_method_agreement), so every
    // mask test checks the compute and the geometry-shader path against each other.
    Mask mask(const std::string& save_as = "");
    void save_color(const std::string& name);
    // For tests that compare frames byte for byte: the classic beam (no flicker, so frames
    // repeat exactly), the compute line method and the vector style.
    void use_repeatable_compute_frames();

    render::RenderSettings settings = render::preset("high");
    bool compare_line_methods = true;
    std::unique_ptr<render::Renderer> renderer;
    scene::MeshLibrary meshes;
    scene::FrameList frame;
};

}  // namespace bz::test
