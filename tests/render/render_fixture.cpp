#include "render/render_fixture.h"

#include <filesystem>

#include "core/image_io.h"

namespace bz::test {

namespace {
std::filesystem::path out_dir() {
    const auto dir = std::filesystem::path(BEAMZONE_BINARY_DIR) / "test-out";
    std::filesystem::create_directories(dir);
    return dir;
}
}  // namespace

void RenderTest::SetUp() {
    GlTest::SetUp();
    renderer = std::make_unique<render::Renderer>(settings, kWidth, kHeight, gl::TimingMethod::off);
}

scene::MeshId RenderTest::add_mesh(const std::string& name, const geo::TriMesh& mesh) {
    return meshes.add(name, geo::build_line_mesh(mesh));
}

void RenderTest::add_item(scene::MeshId id, const glm::dmat4& model) {
    scene::DrawItem item;
    item.mesh = id;
    item.model = model;
    frame.items.push_back(item);
}

Mask RenderTest::mask(const std::string& save_as) {
    renderer->set_settings(settings);
    Mask m{kWidth, kHeight, renderer->render_mask(frame, meshes)};
    if (!save_as.empty()) write_png(out_dir() / (save_as + "_mask.png"), Image{kWidth, kHeight, 1, m.pixels});
    return m;
}

void RenderTest::save_color(const std::string& name) {
    renderer->set_settings(settings);
    renderer->render(frame, meshes, render::Renderer::kOffscreen);
    write_png(out_dir() / (name + ".png"), Image{kWidth, kHeight, 4, renderer->read_color()});
}

}  // namespace bz::test
