#include <gtest/gtest.h>

#include "gl/gl.h"
#include "support/gl_test.h"

using bz::test::GlTest;

TEST_F(GlTest, HeadlessContextIsGl45CoreWithDebugOutput) {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(glIsEnabled(GL_DEBUG_OUTPUT));
}

TEST(GlDebug, AnErrorIsCounted) {
    auto& ctx = bz::test::shared_context();
    ctx.debug().clear();
    ctx.debug().set_echo(false);
    glEnable(0xFFFF);  // invalid enum on purpose
    EXPECT_GE(ctx.debug().error_count(), 1);
    ctx.debug().clear();
    ctx.debug().set_echo(true);
}
