#include "gl/vertex_array.h"

namespace bz::gl {

VertexArray::VertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    handle_ = Handle<VertexArrayDeleter>(id);
}

void VertexArray::bind_buffer(GLuint binding, const Buffer& buffer, GLsizei stride, GLintptr offset,
                              GLuint divisor) {
    glVertexArrayVertexBuffer(id(), binding, buffer.id(), offset, stride);
    glVertexArrayBindingDivisor(id(), binding, divisor);
}

void VertexArray::float_attribute(GLuint location, GLuint binding, GLint components,
                                  GLuint relative_offset) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribFormat(id(), location, components, GL_FLOAT, GL_FALSE, relative_offset);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::uint_attribute(GLuint location, GLuint binding, GLint components,
                                 GLuint relative_offset) {
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribIFormat(id(), location, components, GL_UNSIGNED_INT, relative_offset);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::element_buffer(const Buffer& buffer) {
    glVertexArrayElementBuffer(id(), buffer.id());
}

void VertexArray::bind() const {
    glBindVertexArray(id());
}

}  // namespace bz::gl
