#pragma once
// The GPU side of the edge buffer (edge_buffer.h): the records and the indirect draw command
// whose vertex count is the append counter. The buffer grows, never shrinks; a frame that
// appends more records than fit is counted in full, so the renderer can grow the buffer.
#include <cstddef>
#include <cstdint>

#include "gl/buffer.h"
#include "render/edge_buffer.h"

namespace bz::render {

class EdgeStorage {
public:
    EdgeStorage();
    // Room for at least `records` (capped at what one shader storage block may hold).
    void reserve(std::size_t records);
    // Sets the counter to zero before a fill.
    void reset();
    // Records the last fill appended, including any past capacity(). Reads the counter back:
    // waits for the fill.
    std::size_t appended() const;
    // After a fill: the counter of that fill is copied aside, to be read a frame later without
    // waiting (previous_appended). Grows the buffer when it was too small.
    void keep_count();
    std::size_t previous_appended() const;

    std::uint32_t capacity() const { return capacity_; }
    std::uint32_t max_capacity() const { return max_capacity_; }
    const gl::Buffer& records() const { return records_; }
    const gl::Buffer& command() const { return command_; }

private:
    gl::Buffer records_;
    gl::Buffer command_;
    gl::Buffer kept_count_;
    std::uint32_t capacity_ = 0;
    std::uint32_t max_capacity_ = 0;
};

}  // namespace bz::render
