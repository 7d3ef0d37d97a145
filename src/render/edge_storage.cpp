#include "render/edge_storage.h"

#include <algorithm>

namespace bz::render {

EdgeStorage::EdgeStorage() {
    GLint64 max_block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
    max_capacity_ = static_cast<std::uint32_t>(
        std::min<GLint64>(max_block / static_cast<GLint64>(sizeof(EdgeRecord)), 0x7FFFFFFF / kVerticesPerEdge));
    const EdgeDrawCommand cmd;
    command_.set_data(&cmd, sizeof(cmd), GL_DYNAMIC_DRAW);
    const std::uint32_t zero = 0;
    kept_count_.set_data(&zero, sizeof(zero), GL_DYNAMIC_READ);
    reserve(1024);
}

void EdgeStorage::reserve(std::size_t records) {
    const std::uint32_t want = static_cast<std::uint32_t>(std::min<std::size_t>(records, max_capacity_));
    if (want <= capacity_) return;
    // Grow by at least half again, so a slowly growing scene does not reallocate every frame.
    capacity_ = std::min(max_capacity_, std::max(want, capacity_ + capacity_ / 2));
    records_.set_data(nullptr, static_cast<std::size_t>(capacity_) * sizeof(EdgeRecord), GL_DYNAMIC_COPY);
}

void EdgeStorage::reset() {
    const EdgeDrawCommand cmd;
    glNamedBufferSubData(command_.id(), 0, sizeof(cmd), &cmd);
}

std::size_t EdgeStorage::appended() const {
    std::uint32_t vertices = 0;
    glGetNamedBufferSubData(command_.id(), 0, sizeof(vertices), &vertices);
    return vertices / kVerticesPerEdge;
}

void EdgeStorage::keep_count() {
    glCopyNamedBufferSubData(command_.id(), kept_count_.id(), 0, 0, sizeof(std::uint32_t));
}

std::size_t EdgeStorage::previous_appended() const {
    std::uint32_t vertices = 0;
    glGetNamedBufferSubData(kept_count_.id(), 0, sizeof(vertices), &vertices);
    return vertices / kVerticesPerEdge;
}

}  // namespace bz::render
