#pragma once
#include "gl/handle.h"

namespace bz::gl {

struct TextureDeleter {
    void operator()(GLuint id) const { glDeleteTextures(1, &id); }
};

enum class Filter { nearest, linear };

// An immutable-storage 2D texture (one level), clamped at the edges.
class Texture2D {
  public:
    Texture2D() = default;
    Texture2D(int width, int height, GLenum internal_format, Filter filter);
    void bind(GLuint unit) const;
    GLuint id() const { return handle_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    GLenum format() const { return format_; }
    explicit operator bool() const { return static_cast<bool>(handle_); }

  private:
    Handle<TextureDeleter> handle_;
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
};

}  // namespace bz::gl
