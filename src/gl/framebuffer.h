#pragma once
#include <vector>

#include "gl/handle.h"
#include "gl/texture.h"

namespace bz::gl {

struct FramebufferDeleter {
    void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); }
};

// A framebuffer over textures it does not own. Throws if the attachments are incomplete.
class Framebuffer {
  public:
    Framebuffer() = default;
    Framebuffer(std::vector<const Texture2D*> colors, const Texture2D* depth);
    // Binds for drawing and sets the viewport to the attachment size.
    void bind() const;
    GLuint id() const { return handle_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    Handle<FramebufferDeleter> handle_;
    int width_ = 0;
    int height_ = 0;
};

// The window's (or context's) own framebuffer.
void bind_default_framebuffer(int width, int height);

}  // namespace bz::gl
