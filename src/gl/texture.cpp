#include "gl/texture.h"

namespace bz::gl {

Texture2D::Texture2D(int width, int height, GLenum internal_format, Filter filter)
    : width_(width), height_(height), format_(internal_format) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    handle_ = Handle<TextureDeleter>(id);
    glTextureStorage2D(id, 1, internal_format, width, height);
    const GLint f = filter == Filter::linear ? GL_LINEAR : GL_NEAREST;
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, f);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, f);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Texture2D::bind(GLuint unit) const {
    glBindTextureUnit(unit, handle_.id());
}

}  // namespace bz::gl
