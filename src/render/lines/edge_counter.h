#pragma once
// Feature edges per frame (FrameStats::feature_edges, RenderSettings::count_edges), read back
// `latency` frames late. Reading a count in the frame that made it makes the CPU wait for the
// GPU in the middle of the frame; on a hardware GPU at a millisecond a frame that wait is a
// good part of the frame time that `bench` reports. So the count goes into a per-frame slot
// (a GL_PRIMITIVES_GENERATED query for the geometry shader, a copy of the edge buffer's append
// counter for the compute method) and is read when the frame `latency` frames later ends, as
// the pass timer's queries are (gl::PassTimer::latency). With latency 0 it is read at the end
// of its own frame, which is all a software rasteriser timed with glFinish can do anyway.
#include <cstddef>
#include <vector>

#include "gl/buffer.h"

namespace bz::render {

class EdgeCounter {
  public:
    explicit EdgeCounter(int latency);
    ~EdgeCounter();
    EdgeCounter(const EdgeCounter&) = delete;
    EdgeCounter& operator=(const EdgeCounter&) = delete;

    int latency() const { return static_cast<int>(slots_.size()) - 1; }
    void begin_frame();
    // The geometry shader's line pass: quads generated between these (two triangles each).
    void begin_primitives();
    void end_primitives();
    // The compute method: the records the edges pass appended, from its draw command.
    void count_records(const gl::Buffer& command);
    // Ends the frame; returns the count of the frame `latency` frames ago (0 before any, or
    // when that frame counted nothing).
    std::size_t end_frame();

  private:
    enum class Source { none, primitives, records };
    struct Slot {
        GLuint query = 0;
        gl::Buffer count;  // the draw command's vertex count, copied
        Source source = Source::none;
    };
    std::size_t read(Slot& slot) const;

    std::vector<Slot> slots_;
    std::size_t frame_ = 0;
};

}  // namespace bz::render
