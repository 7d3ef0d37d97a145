#pragma once
// Move-only owner of one GL object name. Each wrapper supplies how its kind is deleted.
#include <utility>

#include "gl/gl.h"

namespace bz::gl {

template <class Deleter>
class Handle {
  public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    void reset() {
        if (id_) Deleter{}(id_);
        id_ = 0;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

  private:
    GLuint id_ = 0;
};

}  // namespace bz::gl
