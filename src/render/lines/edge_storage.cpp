#include "render/lines/edge_storage.h"

#include <algorithm>
#include <vector>

namespace bz::render {

namespace {

// Grows by at least half again, so a slowly growing scene does not reallocate every frame.
std::uint32_t grown(std::uint32_t current, std::size_t want, std::uint32_t max) {
    const auto w = static_cast<std::uint32_t>(std::min<std::size_t>(want, max));
    if (w <= current) return current;
    return std::min(max, std::max(w, current + current / 2));
}

// Two triangles over each record's four corners, in the strip order edge_quad.vert expects.
std::vector<std::uint32_t> quad_corner_indices(std::uint32_t records) {
    std::vector<std::uint32_t> indices;
    indices.reserve(static_cast<std::size_t>(records) * kVerticesPerEdge);
    for (std::uint32_t k = 0; k < records; ++k) {
        const std::uint32_t c = k * kCornersPerEdge;
        for (const std::uint32_t corner : {0u, 1u, 2u, 2u, 1u, 3u}) indices.push_back(c + corner);
    }
    return indices;
}

}  // namespace

EdgeStorage::EdgeStorage() {
    GLint64 max_block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
    max_capacity_ = static_cast<std::uint32_t>(std::min<GLint64>(
        max_block / static_cast<GLint64>(sizeof(EdgeRecord)), 0x7FFFFFFF / kVerticesPerEdge));
    max_samples_ = static_cast<std::uint32_t>(std::min<GLint64>(max_block / 4, 0x7FFFFFFF));
    const EdgeDrawCommand cmd;
    command_.set_data(&cmd, sizeof(cmd), GL_DYNAMIC_DRAW);
    kept_count_.set_data(&cmd, sizeof(cmd), GL_DYNAMIC_READ);
    readback_.set_data(&cmd, sizeof(cmd), GL_DYNAMIC_READ);
    reserve(1024);
    reserve_samples(std::size_t{1} << 18);
}

void EdgeStorage::reserve(std::size_t records) {
    const std::uint32_t next = grown(capacity_, records, max_capacity_);
    if (next == capacity_) return;
    capacity_ = next;
    records_.set_data(nullptr, static_cast<std::size_t>(capacity_) * sizeof(EdgeRecord),
                      GL_DYNAMIC_COPY);
    spans_.set_data(nullptr, static_cast<std::size_t>(capacity_) * 8 * sizeof(std::uint32_t),
                    GL_DYNAMIC_COPY);
    quad_index_buffer_.set(std::span<const std::uint32_t>(quad_corner_indices(capacity_)),
                           GL_STATIC_DRAW);
    quad_vao_.element_buffer(quad_index_buffer_);
}

void EdgeStorage::reserve_samples(std::size_t samples) {
    const std::uint32_t next = grown(sample_capacity_, samples, max_samples_);
    if (next == sample_capacity_) return;
    sample_capacity_ = next;
    samples_.set_data(nullptr, static_cast<std::size_t>(sample_capacity_) * sizeof(std::uint32_t),
                      GL_DYNAMIC_COPY);
}

void EdgeStorage::set_work(std::span<const glm::uvec4> work) {
    work_.set(work, GL_STREAM_DRAW);
}

void EdgeStorage::reset() {
    const EdgeDrawCommand cmd;
    glNamedBufferSubData(command_.id(), 0, sizeof(cmd), &cmd);
}

// The counts are copied into a small buffer meant for reading and read from there: reading
// the draw command itself makes a hardware driver move it, and the shader atomics on it, out of
// video memory into host memory (NVIDIA says so in a KHR_debug performance message).
EdgeDrawCommand EdgeStorage::read_now() const {
    glCopyNamedBufferSubData(command_.id(), readback_.id(), 0, 0, sizeof(EdgeDrawCommand));
    EdgeDrawCommand cmd;
    glGetNamedBufferSubData(readback_.id(), 0, sizeof(cmd), &cmd);
    return cmd;
}

EdgeStorage::FillCounts EdgeStorage::counts() const {
    const EdgeDrawCommand cmd = read_now();
    return {cmd.vertex_count / kVerticesPerEdge, cmd.samples_used, cmd.hidden_items};
}

void EdgeStorage::keep_count() {
    has_previous_ = true;
    previous_.reset();
    glCopyNamedBufferSubData(command_.id(), kept_count_.id(), 0, 0, sizeof(EdgeDrawCommand));
}

void EdgeStorage::forget_previous() {
    has_previous_ = false;
    previous_ = EdgeDrawCommand{};  // what the counts were before the first fill
}

EdgeDrawCommand EdgeStorage::previous() const {
    if (!previous_) {
        EdgeDrawCommand cmd;
        glGetNamedBufferSubData(kept_count_.id(), 0, sizeof(cmd), &cmd);
        previous_ = cmd;
    }
    return *previous_;
}

}  // namespace bz::render
