#include "gl/framebuffer.h"

#include <stdexcept>
#include <string>

namespace bz::gl {

Framebuffer::Framebuffer(std::vector<const Texture2D*> colors, const Texture2D* depth) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    handle_ = Handle<FramebufferDeleter>(id);
    std::vector<GLenum> draw_buffers;
    for (std::size_t i = 0; i < colors.size(); ++i) {
        const auto attachment = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i);
        glNamedFramebufferTexture(id, attachment, colors[i]->id(), 0);
        draw_buffers.push_back(attachment);
        width_ = colors[i]->width();
        height_ = colors[i]->height();
    }
    if (depth) {
        glNamedFramebufferTexture(id, GL_DEPTH_ATTACHMENT, depth->id(), 0);
        width_ = depth->width();
        height_ = depth->height();
    }
    if (draw_buffers.empty()) {
        glNamedFramebufferDrawBuffer(id, GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(id, static_cast<GLsizei>(draw_buffers.size()),
                                      draw_buffers.data());
    }
    const GLenum status = glCheckNamedFramebufferStatus(id, GL_DRAW_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("framebuffer incomplete: status 0x" + std::to_string(status));
    }
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, handle_.id());
    glViewport(0, 0, width_, height_);
}

void bind_default_framebuffer(int width, int height) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
}

}  // namespace bz::gl
