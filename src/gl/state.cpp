#include "gl/state.h"

namespace bz::gl {

void apply(const PipelineState& s) {
    if (s.depth_test == DepthTest::off) {
        glDisable(GL_DEPTH_TEST);
    } else {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(s.depth_test == DepthTest::less      ? GL_LESS
                    : s.depth_test == DepthTest::greater ? GL_GREATER
                                                         : GL_ALWAYS);
    }
    glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    const GLboolean c = s.color_write ? GL_TRUE : GL_FALSE;
    glColorMask(c, c, c, c);
    switch (s.blend) {
        case Blend::none:
            glDisable(GL_BLEND);
            break;
        case Blend::max:
            glEnable(GL_BLEND);
            glBlendEquation(GL_MAX);
            break;
        case Blend::add:
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE);
            break;
        case Blend::min:
            glEnable(GL_BLEND);
            glBlendEquation(GL_MIN);
            break;
        case Blend::alpha:
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            break;
    }
    if (s.cull_back) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    glClipControl(GL_LOWER_LEFT, s.depth_zero_to_one ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    if (s.scissor_rows > 0) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, s.scissor_width, s.scissor_rows);
    } else {
        glDisable(GL_SCISSOR_TEST);
    }
    if (s.depth_clamp) {
        glEnable(GL_DEPTH_CLAMP);
    } else {
        glDisable(GL_DEPTH_CLAMP);
    }
}

}  // namespace bz::gl
