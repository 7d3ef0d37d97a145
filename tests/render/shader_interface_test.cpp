// The typed shader interface (render/shader_interface.h): the GLSL side reads InstanceData as
// C++ writes it, every program's samplers sit on distinct units, and no shader types a binding
// number or the instance layout by hand.
#include "render/shader_interface.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/paths.h"
#include "gl/buffer.h"
#include "render/gpu_scene/mesh_cache.h"
#include "render/programs.h"
#include "support/gl_test.h"
#include "support/scratch_dir.h"

namespace {

using bz::render::InstanceData;
namespace fs = std::filesystem;

class ShaderInterfaceTest : public bz::test::GlTest {};

// A compute shader reads three instances through shaders/instance_data.glsl's accessors and
// copies what it reads: it must be what C++ wrote, field by field.
TEST_F(ShaderInterfaceTest, TheShadersReadInstanceDataAsCppWritesIt) {
    const bz::test::ScratchDir scratch("bz_instance_layout");
    const fs::path include = bz::shaders_dir() / "instance_data.glsl";
    const fs::path comp = scratch.write("read_instances.comp", R"(#version 450 core
layout(local_size_x = 1) in;
#include ")" + include.string() + R"("
layout(std430, binding = 7) writeonly buffer Out { vec4 read_back[]; };
void main() {
    uint i = gl_GlobalInvocationID.x;
    mat4 m = instance_model_view(i);
    for (uint c = 0u; c < 4u; ++c) read_back[i * 6u + c] = m[c];
    read_back[i * 6u + 4u] = instance_color(i);
    read_back[i * 6u + 5u] = instance_params(i);
}
)");
    const bz::gl::Program program({{GL_COMPUTE_SHADER, comp}},
                                  bz::render::shader_interface_defines());
    std::vector<InstanceData> instances(3);
    float v = 1.0f;
    for (InstanceData& d : instances) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) d.model_view[c][r] = v++;
        d.color = glm::vec4(v, v + 1.0f, v + 2.0f, v + 3.0f);
        d.params = glm::vec4(v + 4.0f, v + 5.0f, v + 6.0f, v + 7.0f);
        v += 8.0f;
    }
    bz::gl::Buffer in, out;
    in.set(std::span<const InstanceData>(instances));
    std::vector<glm::vec4> zeros(instances.size() * 6, glm::vec4(0.0f));
    out.set(std::span<const glm::vec4>(zeros));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bz::render::kInstancesBinding, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, out.id());
    program.use();
    glDispatchCompute(static_cast<GLuint>(instances.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> read(zeros.size());
    glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(read.size() * sizeof(glm::vec4)),
                            read.data());
    for (std::size_t i = 0; i < instances.size(); ++i) {
        for (int c = 0; c < 4; ++c)
            EXPECT_EQ(read[i * 6 + c], instances[i].model_view[c]) << "instance " << i;
        EXPECT_EQ(read[i * 6 + 4], instances[i].color) << "instance " << i;
        EXPECT_EQ(read[i * 6 + 5], instances[i].params) << "instance " << i;
    }
}

std::vector<std::pair<std::string, const bz::gl::Program*>> every_program(
    const bz::render::Programs& p) {
    std::vector<std::pair<std::string, const bz::gl::Program*>> all = {
        {"prepass", &p.prepass},
        {"prepass_raster", &p.prepass_raster},
        {"depth_resolve", &p.depth_resolve},
        {"occlusion_layer", &p.occlusion_layer},
        {"lines_dim", &p.lines_dim},
        {"edge_quads_dim.sampled", &p.edge_quads_dim.sampled},
        {"edge_quads_dim.tested", &p.edge_quads_dim.tested},
        {"outline_levels_mask", &p.outline_levels_mask},
        {"lines", &p.lines},
        {"mask", &p.mask},
        {"edges", &p.edges},
        {"spine_visibility", &p.spine_visibility},
        {"intersections", &p.intersections},
        {"depth_tiles", &p.depth_tiles},
        {"edges_listed", &p.edges_listed},
        {"edges_normals", &p.edges_normals},
        {"edges_listed_normals", &p.edges_listed_normals},
        {"edge_quads.sampled", &p.edge_quads.sampled},
        {"edge_quads.tested", &p.edge_quads.tested},
        {"edge_quads_mask.sampled", &p.edge_quads_mask.sampled},
        {"edge_quads_mask.tested", &p.edge_quads_mask.tested},
        {"hud", &p.hud},
        {"hud_lit_tiles", &p.hud_lit_tiles},
        {"bloom_down", &p.bloom_down},
        {"bloom_down_tiles", &p.bloom_down_tiles},
        {"bloom_blur", &p.bloom_blur},
        {"bloom_blur_glow", &p.bloom_blur_glow},
        {"composite", &p.composite},
        {"composite_tiles", &p.composite_tiles},
        {"composite_phosphor[0]", &p.composite_phosphor[0]},
        {"composite_phosphor[1]", &p.composite_phosphor[1]},
        {"composite_tiles_phosphor[0]", &p.composite_tiles_phosphor[0]},
        {"composite_tiles_phosphor[1]", &p.composite_tiles_phosphor[1]},
        {"tile_list", &p.tile_list},
        {"clear_image", &p.clear_image},
        {"bloom_chain", &p.bloom_chain},
        {"bloom_up", &p.bloom_up},
        {"bloom_up_glow", &p.bloom_up_glow},
        {"outline_prepass", &p.outline_prepass},
        {"image_outline", &p.image_outline},
        {"image_outline_mask", &p.image_outline_mask},
        {"fill_toon", &p.fill_toon},
        {"fill_pop_art", &p.fill_pop_art},
        {"fill_paper", &p.fill_paper},
        {"shrunk_depth", &p.shrunk_depth},
        {"ink_composite", &p.ink_composite},
        {"ink_composite_tiles", &p.ink_composite_tiles},
        {"outline", &p.outline},
        {"sketch", &p.sketch},
        {"sketch_mask", &p.sketch_mask},
        {"halo_glow", &p.halo_glow},
        {"halo", &p.halo},
        {"halo_apply", &p.halo_apply},
        {"halo_apply_tiles", &p.halo_apply_tiles},
    };
    return all;
}

bool is_sampler(GLenum type) {
    switch (type) {
        case GL_SAMPLER_2D:
        case GL_INT_SAMPLER_2D:
        case GL_UNSIGNED_INT_SAMPLER_2D:
        case GL_SAMPLER_2D_SHADOW:
        case GL_SAMPLER_3D:
        case GL_SAMPLER_CUBE:
            return true;
        default:
            return false;
    }
}

// Units are fixed at link by layout(binding = TEXTURE_UNIT_*): two samplers of one program on
// one unit would read the same texture.
TEST_F(ShaderInterfaceTest, EveryProgramsSamplersSitOnDistinctUnits) {
    const bz::render::Programs programs = bz::render::load_programs(bz::render::preset("high"));
    const auto all = every_program(programs);
    EXPECT_EQ(all.size() * sizeof(bz::gl::Program), sizeof(bz::render::Programs))
        << "a program was added to render::Programs: list it in every_program()";
    int samplers_seen = 0;
    for (const auto& [name, program] : all) {
        ASSERT_TRUE(*program) << name;
        GLint count = 0;
        glGetProgramInterfaceiv(program->id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
        std::map<GLint, std::string> units;
        for (GLint i = 0; i < count; ++i) {
            const GLenum props[] = {GL_TYPE, GL_LOCATION};
            GLint values[2] = {};
            glGetProgramResourceiv(program->id(), GL_UNIFORM, static_cast<GLuint>(i), 2, props, 2,
                                   nullptr, values);
            if (!is_sampler(static_cast<GLenum>(values[0]))) continue;
            char uniform[128] = {};
            glGetProgramResourceName(program->id(), GL_UNIFORM, static_cast<GLuint>(i),
                                     sizeof(uniform), nullptr, uniform);
            GLint unit = -1;
            glGetUniformiv(program->id(), values[1], &unit);
            const auto [it, fresh] = units.emplace(unit, uniform);
            EXPECT_TRUE(fresh) << name << ": " << uniform << " and " << it->second
                               << " share texture unit " << unit;
            ++samplers_seen;
        }
    }
    EXPECT_GT(samplers_seen, 20);  // the premise: the samplers were found
}

// The numbers live in shader_interface.h and edge_buffer.h only: no shader under shaders/ names
// a binding point or unit by number, and only instance_data.glsl indexes the instance buffer.
TEST(ShaderInterface, NoShaderTypesABindingOrTheInstanceLayoutByHand) {
    const std::regex numbered_binding(R"(binding\s*=\s*[0-9])");
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(bz::shaders_dir())) {
        if (!entry.is_regular_file()) continue;
        ++files;
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const std::string s = text.str();
        const std::string name = entry.path().filename().string();
        EXPECT_FALSE(std::regex_search(s, numbered_binding)) << name << " numbers a binding";
        if (name != "instance_data.glsl") {
            EXPECT_EQ(s.find("instance_data["), std::string::npos)
                << name << " indexes the instance buffer by hand";
            EXPECT_EQ(s.find("readonly buffer Instances"), std::string::npos)
                << name << " declares the instance buffer itself";
        }
    }
    EXPECT_GT(files, 30);
}

}  // namespace
