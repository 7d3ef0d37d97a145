#include "gl/buffer.h"

namespace bz::gl {

Buffer::Buffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    handle_ = Handle<BufferDeleter>(id);
}

void Buffer::set_data(const void* data, std::size_t bytes, GLenum usage) {
    // Orphan-and-refill: a zero-size store is not allowed, so keep at least one byte.
    glNamedBufferData(handle_.id(), static_cast<GLsizeiptr>(bytes ? bytes : 1),
                      bytes ? data : nullptr, usage);
    size_ = bytes;
}

}  // namespace bz::gl
