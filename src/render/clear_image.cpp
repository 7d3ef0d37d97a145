#include "render/clear_image.h"

#include "render/passes.h"

namespace bz::render {

bool clears_by_compute(const RenderSettings& settings, bool software_rasteriser) {
    switch (settings.colour_clears) {
        case ColourClears::pipeline:
            return false;
        case ColourClears::compute:
            return true;
        case ColourClears::automatic:
            break;
    }
    return !software_rasteriser;
}

void clear_colour(const PassContext& ctx, const gl::Texture2D& image, glm::vec4 value) {
    if (!clears_by_compute(ctx.settings, ctx.software_rasteriser)) {
        glClearColor(value.r, value.g, value.b, value.a);
        glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    constexpr int kGroup = 16;  // clear_image.comp's local size
    const gl::Program& p = ctx.programs.clear_image;
    p.use();
    p.set("u_value", value);
    glBindImageTexture(kImageUnitClear, image.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, image.format());
    glDispatchCompute(static_cast<GLuint>((image.width() + kGroup - 1) / kGroup),
                      static_cast<GLuint>((image.height() + kGroup - 1) / kGroup), 1);
    // What follows draws into it, samples it or loads it as an image.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace bz::render
