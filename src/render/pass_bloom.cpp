#include "render/passes.h"

namespace bz::render {

// Downsample to the bloom resolution, then a separable linear-sampled Gaussian: horizontal
// into bloom_b, vertical back into bloom_a.
void pass_bloom(const PassContext& ctx) {
    Targets& t = ctx.targets;
    gl::apply(gl::PipelineState{});
    ctx.empty_vao.bind();

    t.bloom_a_fbo.bind();
    const gl::Program& down = ctx.programs.bloom_down;
    down.use();
    down.set("u_source", 0);
    down.set("u_factor", static_cast<int>(ctx.settings.bloom_resolution));
    t.lines.bind(0);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    const gl::Program& blur = ctx.programs.bloom_blur;  // kernel baked in (programs.cpp)
    blur.use();
    blur.set("u_source", 0);

    t.bloom_b_fbo.bind();
    blur.set("u_direction", glm::vec2(1.0f, 0.0f));
    t.bloom_a.bind(0);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    t.bloom_a_fbo.bind();
    blur.set("u_direction", glm::vec2(0.0f, 1.0f));
    t.bloom_b.bind(0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace bz::render
