#include "render/clear_image.h"

#include <algorithm>
#include <array>
#include <limits>

#include "gl/framebuffer.h"
#include "render/passes.h"

namespace bz::render {

namespace {

void clear_by_compute(const gl::Program& clear_image, const gl::Texture2D& image, glm::vec4 value) {
    constexpr int kGroup = 16;  // clear_image.comp's local size
    clear_image.use();
    clear_image.set("u_value", value);
    glBindImageTexture(kImageUnitClear, image.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, image.format());
    glDispatchCompute(static_cast<GLuint>((image.width() + kGroup - 1) / kGroup),
                      static_cast<GLuint>((image.height() + kGroup - 1) / kGroup), 1);
    // What follows draws into it, samples it or loads it as an image.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void clear_by_pipeline(glm::vec4 value) {
    glClearColor(value.r, value.g, value.b, value.a);
    glClear(GL_COLOR_BUFFER_BIT);
}

}  // namespace

ClearPath clear_path(const RenderSettings& settings, bool software_rasteriser) {
    switch (settings.colour_clears) {
        case ColourClears::pipeline:
            return ClearPath::pipeline;
        case ColourClears::compute:
            return ClearPath::compute;
        case ColourClears::automatic:
            break;
    }
    return software_rasteriser ? ClearPath::pipeline : ClearPath::measure;
}

ClearTiming time_colour_clears(const gl::Program& clear_image, int width, int height) {
    constexpr int kRounds = 4;  // the first warms both paths up and is not counted
    const gl::Texture2D image(width, height, GL_RGBA16F, gl::Filter::nearest);
    const gl::Framebuffer fbo({&image}, nullptr);
    std::array<GLuint, 2 * kRounds> queries{};
    glGenQueries(static_cast<GLsizei>(queries.size()), queries.data());
    fbo.bind();
    gl::apply(gl::PipelineState{});
    for (int r = 0; r < kRounds; ++r) {
        glBeginQuery(GL_TIME_ELAPSED, queries[static_cast<std::size_t>(2 * r)]);
        clear_by_pipeline(glm::vec4(0.0f));
        glEndQuery(GL_TIME_ELAPSED);
        glBeginQuery(GL_TIME_ELAPSED, queries[static_cast<std::size_t>(2 * r + 1)]);
        clear_by_compute(clear_image, image, glm::vec4(0.0f));
        glEndQuery(GL_TIME_ELAPSED);
    }
    ClearTiming best{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    for (int r = 1; r < kRounds; ++r) {
        GLuint64 ns[2] = {};
        glGetQueryObjectui64v(queries[static_cast<std::size_t>(2 * r)], GL_QUERY_RESULT, &ns[0]);
        glGetQueryObjectui64v(queries[static_cast<std::size_t>(2 * r + 1)], GL_QUERY_RESULT,
                              &ns[1]);
        best.pipeline_ms = std::min(best.pipeline_ms, static_cast<double>(ns[0]) * 1e-6);
        best.compute_ms = std::min(best.compute_ms, static_cast<double>(ns[1]) * 1e-6);
    }
    glDeleteQueries(static_cast<GLsizei>(queries.size()), queries.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return best;
}

void clear_colour(const PassContext& ctx, const gl::Texture2D& image, glm::vec4 value) {
    if (ctx.clears_by_compute)
        clear_by_compute(ctx.programs.clear_image, image, value);
    else
        clear_by_pipeline(value);
}

}  // namespace bz::render
