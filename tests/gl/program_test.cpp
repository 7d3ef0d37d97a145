// gl::Program's uniform table: locations read once at link; a name the source does not declare
// is a GL error the tests fail on, a declared one the compiler dropped is not.
#include "gl/program.h"

#include <gtest/gtest.h>

#include "support/gl_test.h"
#include "support/scratch_dir.h"

namespace {

using bz::test::GlTest;

constexpr const char* kVertex = R"(#version 450 core
void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }
)";
// u_unused is declared but never read, so the linker drops it; u_variant only exists in the
// VARIANT build; u_weights is an array.
constexpr const char* kFragment = R"(#version 450 core
uniform vec4 u_color;
uniform float u_weights[3];
uniform float u_unused;
#ifdef VARIANT
uniform float u_variant;
#endif
out vec4 o_color;
void main() { o_color = u_color * (u_weights[0] + u_weights[2]); }
)";

class ProgramUniforms : public GlTest {
  protected:
    bz::gl::Program build() {
        const auto vert = scratch_.write("p.vert", kVertex);
        const auto frag = scratch_.write("p.frag", kFragment);
        return bz::gl::Program({{GL_VERTEX_SHADER, vert}, {GL_FRAGMENT_SHADER, frag}});
    }
    int errors() { return context().debug().error_count(); }
    bz::test::ScratchDir scratch_{"bz_program"};
};

TEST_F(ProgramUniforms, ActiveUniformsHaveTheirGlLocations) {
    const auto p = build();
    EXPECT_EQ(p.location("u_color"), glGetUniformLocation(p.id(), "u_color"));
    EXPECT_GE(p.location("u_color"), 0);
    EXPECT_EQ(p.location("u_weights"), glGetUniformLocation(p.id(), "u_weights"));
    const float w[3] = {0.25f, 0.5f, 0.75f};
    p.set_array("u_weights", w, 3);
    p.set("u_color", glm::vec4(1.0f));
    GLfloat read[4] = {};
    glGetUniformfv(p.id(), glGetUniformLocation(p.id(), "u_weights[2]"), read);
    EXPECT_EQ(read[0], 0.75f);
    EXPECT_EQ(errors(), 0);
}

TEST_F(ProgramUniforms, DeclaredButInactiveIsSkippedWithoutError) {
    const auto p = build();
    EXPECT_EQ(glGetUniformLocation(p.id(), "u_unused"), -1);  // the premise: GL dropped it
    p.set("u_unused", 1.0f);
    p.set("u_variant", 2.0f);  // declared in a branch this build compiled out
    EXPECT_TRUE(p.declares("u_unused"));
    EXPECT_EQ(errors(), 0);
}

TEST_F(ProgramUniforms, AMisspelledNameIsAGlError) {
    const auto p = build();
    context().debug().set_echo(false);
    p.set("u_colour", glm::vec4(1.0f));
    const int reported = errors();
    const auto messages = context().debug().messages();
    p.set("u_colour", glm::vec4(1.0f));  // reported once per program and name
    const int again = errors();
    context().debug().clear();  // the errors were the point; TearDown checks for others
    context().debug().set_echo(true);
    EXPECT_EQ(reported, 1);
    EXPECT_EQ(again, 1);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_NE(messages[0].find("u_colour"), std::string::npos);
    EXPECT_NE(messages[0].find("p.frag"), std::string::npos);
}

}  // namespace
