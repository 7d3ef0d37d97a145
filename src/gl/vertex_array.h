#pragma once
#include "gl/buffer.h"
#include "gl/handle.h"

namespace bz::gl {

struct VertexArrayDeleter {
    void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); }
};

// Vertex layout through DSA: buffers attach to binding points, attributes read from bindings.
class VertexArray {
  public:
    VertexArray();
    void bind_buffer(GLuint binding, const Buffer& buffer, GLsizei stride, GLintptr offset = 0,
                     GLuint divisor = 0);
    void float_attribute(GLuint location, GLuint binding, GLint components, GLuint relative_offset);
    void uint_attribute(GLuint location, GLuint binding, GLint components, GLuint relative_offset);
    void element_buffer(const Buffer& buffer);
    void bind() const;
    GLuint id() const { return handle_.id(); }

  private:
    Handle<VertexArrayDeleter> handle_;
};

}  // namespace bz::gl
