// The edge buffer's GPU side (render/lines/edge_storage.h): the quads of spine_visibility.comp's
// draws are indexed through EdgeStorage::quad_indices, two triangles over each record's four
// corners in the order edge_quad.vert places them, for every record the buffer holds - also
// after it grows - so that no draw, whose count stops at the capacity, reads past the indices.
#include "render/lines/edge_storage.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/gl_test.h"

namespace bz::test {
namespace {

class EdgeStorageTest : public GlTest {};

// The element buffer bound to the storage's vertex array, read back whole.
std::vector<std::uint32_t> quad_indices_of(const render::EdgeStorage& storage) {
    GLint buffer = 0;
    glGetVertexArrayiv(storage.quad_indices().id(), GL_ELEMENT_ARRAY_BUFFER_BINDING, &buffer);
    EXPECT_NE(buffer, 0) << "no element buffer on the quads' vertex array";
    GLint64 bytes = 0;
    glGetNamedBufferParameteri64v(static_cast<GLuint>(buffer), GL_BUFFER_SIZE, &bytes);
    std::vector<std::uint32_t> indices(static_cast<std::size_t>(bytes) / sizeof(std::uint32_t));
    glGetNamedBufferSubData(static_cast<GLuint>(buffer), 0, bytes, indices.data());
    return indices;
}

void expect_two_triangles_per_record(const std::vector<std::uint32_t>& indices,
                                     std::uint32_t records) {
    ASSERT_EQ(indices.size(), std::size_t{records} * render::kVerticesPerEdge);
    const std::uint32_t corners[6] = {0, 1, 2, 2, 1, 3};  // edge_quad.vert's strip order
    for (std::uint32_t k = 0; k < records; ++k) {
        for (std::uint32_t i = 0; i < 6; ++i) {
            const std::uint32_t want = k * render::kCornersPerEdge + corners[i];
            ASSERT_EQ(indices[k * 6 + i], want) << "record " << k << ", index " << i;
        }
    }
}

TEST_F(EdgeStorageTest, QuadIndicesCoverEveryRecordTheBufferHolds) {
    render::EdgeStorage storage;
    ASSERT_GT(storage.capacity(), 0u);
    expect_two_triangles_per_record(quad_indices_of(storage), storage.capacity());
}

TEST_F(EdgeStorageTest, QuadIndicesGrowWithTheRecords) {
    render::EdgeStorage storage;
    const std::uint32_t first = storage.capacity();
    storage.reserve(std::size_t{first} * 3 + 7);
    ASSERT_GE(storage.capacity(), first * 3 + 7);
    expect_two_triangles_per_record(quad_indices_of(storage), storage.capacity());
    // Asking for fewer keeps what there is.
    const std::uint32_t grown = storage.capacity();
    storage.reserve(16);
    EXPECT_EQ(storage.capacity(), grown);
    EXPECT_EQ(quad_indices_of(storage).size(), std::size_t{grown} * 6);
}

}  // namespace
}  // namespace bz::test
