#include "gl/shader_source.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;

namespace {
void write(const fs::path& p, const std::string& s) {
    std::ofstream(p) << s;
}
}  // namespace

TEST(ShaderSource, IncludesAndDefinesKeepLineNumbers) {
    const bz::test::ScratchDir scratch("bz_shader_src");
    const fs::path& dir = scratch.path();
    write(dir / "main.frag", "#version 450 core\n#include \"common.glsl\"\nvoid main() {}\n");
    write(dir / "common.glsl", "float f() { return 1.0; }\n");
    const auto src = bz::gl::assemble_shader(dir / "main.frag", {"MASK 1"});
    ASSERT_EQ(src.files.size(), 2u);
    EXPECT_NE(src.text.find("#define MASK 1"), std::string::npos);
    EXPECT_NE(src.text.find("#line 1 1\nfloat f()"), std::string::npos);
    EXPECT_NE(src.text.find("#line 3 0\nvoid main"), std::string::npos);
}

TEST(ShaderSource, MapsMesaAndNvidiaLogsToFileLine) {
    const std::vector<std::string> files = {"shaders/a.frag", "shaders/b.glsl"};
    EXPECT_EQ(bz::gl::map_info_log("1:7(12): error: `x' undeclared\n", files),
              "shaders/b.glsl:7:12: error: `x' undeclared\n");
    EXPECT_EQ(bz::gl::map_info_log("0(3) : error C1008: undefined variable\n", files),
              "shaders/a.frag:3:1: error C1008: undefined variable\n");
}

TEST(ShaderSource, MissingFileAndCycleAreUserErrors) {
    EXPECT_THROW(bz::gl::assemble_shader("/nonexistent.frag"), bz::UserError);
    const bz::test::ScratchDir scratch("bz_shader_cycle");
    const fs::path& dir = scratch.path();
    write(dir / "a.frag", "#version 450 core\n#include \"b.glsl\"\n");
    write(dir / "b.glsl", "#include \"b.glsl\"\n");
    EXPECT_THROW(bz::gl::assemble_shader(dir / "a.frag"), bz::UserError);
}

TEST(ShaderSource, ACycleIsFoundHoweverThePathIsSpelt) {
    const bz::test::ScratchDir scratch("bz_shader_spelling");
    const fs::path& dir = scratch.path();
    fs::create_directory(dir / "sub");
    write(dir / "a.frag", "#version 450 core\n#include \"x.glsl\"\n");
    for (const std::string self : {"./x.glsl", "sub/../x.glsl", ".//x.glsl"}) {
        write(dir / "x.glsl", "#include \"" + self + "\"\n");
        EXPECT_THROW(bz::gl::assemble_shader(dir / "a.frag"), bz::UserError) << self;
    }
    fs::create_symlink(dir / "x.glsl", dir / "alias.glsl");
    write(dir / "x.glsl", "#include \"alias.glsl\"\n");
    EXPECT_THROW(bz::gl::assemble_shader(dir / "a.frag"), bz::UserError);
}

TEST(ShaderSource, ADiamondIsPastedOnceNotExponentially) {
    // Level k includes level k+1 twice, 30 levels deep: 2^30 pastes if each include were
    // expanded, one paste per file when the graph is walked by resolved path.
    const bz::test::ScratchDir scratch("bz_shader_diamond");
    const fs::path& dir = scratch.path();
    constexpr int kLevels = 30;
    write(dir / "main.frag", "#version 450 core\n#include \"d0.glsl\"\nvoid main() {}\n");
    for (int k = 0; k < kLevels; ++k) {
        const std::string next = "d" + std::to_string(k + 1) + ".glsl";
        write(dir / ("d" + std::to_string(k) + ".glsl"),
              "#include \"" + next + "\"\n#include \"./" + next + "\"\nfloat f" +
                  std::to_string(k) + "() { return 1.0; }\n");
    }
    write(dir / ("d" + std::to_string(kLevels) + ".glsl"), "float leaf() { return 0.0; }\n");
    const auto src = bz::gl::assemble_shader(dir / "main.frag");
    EXPECT_EQ(src.files.size(), static_cast<std::size_t>(kLevels + 2));
    EXPECT_LT(src.text.size(), 8000u);
    std::size_t leaves = 0;
    for (std::size_t p = 0; (p = src.text.find("float leaf()", p)) != std::string::npos; ++p)
        ++leaves;
    EXPECT_EQ(leaves, 1u);
}

TEST(ShaderSource, TheAssembledSizeAndTheDepthAreBounded) {
    const bz::test::ScratchDir scratch("bz_shader_budget");
    const fs::path& dir = scratch.path();
    // Eight distinct files of 900 KB: each under the per-file cap, together over the total.
    std::string main = "#version 450 core\n";
    for (int i = 0; i < 8; ++i) {
        const std::string name = "big" + std::to_string(i) + ".glsl";
        write(dir / name, std::string(900 * 1024, ' ') + "\n");
        main += "#include \"" + name + "\"\n";
    }
    write(dir / "main.frag", main);
    EXPECT_THROW(bz::gl::assemble_shader(dir / "main.frag"), bz::UserError);
    // A chain 100 files deep.
    write(dir / "deep.frag", "#version 450 core\n#include \"c0.glsl\"\n");
    for (int k = 0; k < 100; ++k)
        write(dir / ("c" + std::to_string(k) + ".glsl"),
              "#include \"c" + std::to_string(k + 1) + ".glsl\"\n");
    write(dir / "c100.glsl", "\n");
    EXPECT_THROW(bz::gl::assemble_shader(dir / "deep.frag"), bz::UserError);
}

TEST(ShaderSource, AnIncludeThatIsNotARegularFileIsAnErrorNotAHang) {
    const bz::test::ScratchDir scratch("bz_shader_fifo");
    const fs::path& dir = scratch.path();
    ASSERT_EQ(::mkfifo((dir / "fifo.glsl").c_str(), 0644), 0);
    write(dir / "a.frag", "#version 450 core\n#include \"fifo.glsl\"\n");
    EXPECT_THROW(bz::gl::assemble_shader(dir / "a.frag"), bz::UserError);
}

TEST(ShaderSource, DeclaredUniformsAreReadFromTheDeclarations) {
    const std::string glsl = R"(#version 450 core
layout(r8ui, binding = 3) uniform writeonly uimage2D u_tiles;
uniform float u_a, u_b[4], u_c = 1.0;
uniform highp vec2 u_d;  // uniform float u_commented;
/* uniform float u_block_commented; */
uniform Block { float u_in_block; } blk;
#ifdef NEVER
uniform mat4 u_compiled_out;
#endif
float u_not_uniform;
const float k_weights[2] = float[](0.5, 0.5);
void main() {}
)";
    const std::vector<std::string> expected = {"u_a", "u_b",    "u_c", "u_compiled_out",
                                               "u_d", "u_tiles"};
    EXPECT_EQ(bz::gl::declared_uniforms(glsl), expected);
}
