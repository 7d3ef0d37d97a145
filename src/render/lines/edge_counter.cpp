#include "render/lines/edge_counter.h"

#include <algorithm>
#include <cstdint>

#include "render/lines/edge_buffer.h"

namespace bz::render {

EdgeCounter::EdgeCounter(int latency) : slots_(static_cast<std::size_t>(std::max(latency, 0)) + 1) {
    for (Slot& s : slots_) {
        glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &s.query);
        const std::uint32_t zero = 0;
        s.count.set_data(&zero, sizeof(zero), GL_DYNAMIC_READ);
    }
}

EdgeCounter::~EdgeCounter() {
    for (Slot& s : slots_) glDeleteQueries(1, &s.query);
}

void EdgeCounter::begin_frame() {
    slots_[frame_ % slots_.size()].source = Source::none;
}

void EdgeCounter::begin_primitives() {
    glBeginQuery(GL_PRIMITIVES_GENERATED, slots_[frame_ % slots_.size()].query);
}

void EdgeCounter::end_primitives() {
    glEndQuery(GL_PRIMITIVES_GENERATED);
    slots_[frame_ % slots_.size()].source = Source::primitives;
}

void EdgeCounter::count_records(const gl::Buffer& command) {
    Slot& s = slots_[frame_ % slots_.size()];
    glCopyNamedBufferSubData(command.id(), s.count.id(), offsetof(EdgeDrawCommand, vertex_count), 0,
                             sizeof(std::uint32_t));
    s.source = Source::records;
}

std::size_t EdgeCounter::read(Slot& slot) const {
    switch (slot.source) {
        case Source::primitives: {
            GLuint64 prims = 0;
            glGetQueryObjectui64v(slot.query, GL_QUERY_RESULT, &prims);
            return static_cast<std::size_t>(prims / 2);  // two triangles per quad
        }
        case Source::records: {
            std::uint32_t vertices = 0;
            glGetNamedBufferSubData(slot.count.id(), 0, sizeof(vertices), &vertices);
            return vertices / kVerticesPerEdge;
        }
        case Source::none:
            break;
    }
    return 0;
}

std::size_t EdgeCounter::end_frame() {
    const std::size_t lag = slots_.size() - 1;
    std::size_t count = 0;
    if (frame_ >= lag) {
        Slot& done = slots_[(frame_ - lag) % slots_.size()];
        count = read(done);
        done.source = Source::none;
    }
    ++frame_;
    return count;
}

}  // namespace bz::render
