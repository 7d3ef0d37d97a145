#pragma once
#include <cstddef>
#include <span>

#include "gl/handle.h"

namespace bz::gl {

struct BufferDeleter {
    void operator()(GLuint id) const { glDeleteBuffers(1, &id); }
};

// A GL buffer object. Data is (re)specified whole; size() is in bytes.
class Buffer {
  public:
    Buffer();
    template <class T>
    explicit Buffer(std::span<const T> data, GLenum usage = GL_STATIC_DRAW) : Buffer() {
        set_data(data.data(), data.size_bytes(), usage);
    }
    void set_data(const void* data, std::size_t bytes, GLenum usage = GL_STATIC_DRAW);
    template <class T>
    void set(std::span<const T> data, GLenum usage = GL_DYNAMIC_DRAW) {
        set_data(data.data(), data.size_bytes(), usage);
    }
    GLuint id() const { return handle_.id(); }
    std::size_t size() const { return size_; }

  private:
    Handle<BufferDeleter> handle_;
    std::size_t size_ = 0;
};

}  // namespace bz::gl
