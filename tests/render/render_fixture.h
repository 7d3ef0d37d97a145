#pragma once
// A renderer on the shared headless context, plus helpers to render masks and save PNGs of
// what the tests look at (build/test-out/*.png).
#include <memory>
#include <string>

#include "geometry/line_mesh.h"
#include "render/mask_expect.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace bz::test {

class RenderTest : public GlTest {
protected:
    static constexpr int kWidth = 320;
    static constexpr int kHeight = 240;

    void SetUp() override;
    scene::MeshId add_mesh(const std::string& name, const geo::TriMesh& mesh);
    void add_item(scene::MeshId id, const glm::dmat4& model = glm::dmat4(1.0));
    Mask mask(const std::string& save_as = "");
    void save_color(const std::string& name);

    render::RenderSettings settings = render::preset("high");
    std::unique_ptr<render::Renderer> renderer;
    scene::MeshLibrary meshes;
    scene::FrameList frame;
};

}  // namespace bz::test
