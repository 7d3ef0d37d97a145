#include "gl/shader_source.h"

#include <gtest/gtest.h>

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
