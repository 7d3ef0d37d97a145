#pragma once
// The GPU side of the edge buffer (edge_buffer.h): the records, the indirect draw command
// whose vertex count is the append counter, and the spine-visibility samples of the records
// (spine_samples.glsl). The buffers grow, never shrink; a frame that appends more records or
// samples than fit is counted in full, so the renderer can grow the buffers.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "render/lines/edge_buffer.h"

namespace bz::render {

class EdgeStorage {
  public:
    EdgeStorage();
    // Room for at least `records` (capped at what one shader storage block may hold).
    void reserve(std::size_t records);
    // Room for at least `samples` spine samples (same cap).
    void reserve_samples(std::size_t samples);
    // Sets the counters to zero before a fill.
    void reset();
    // What the last fill asked for: the records it appended, including any past capacity(),
    // and the spine samples, including any past sample_capacity(). One read-back of the
    // counters: waits for the fill.
    struct FillCounts {
        std::size_t records = 0;
        std::size_t samples = 0;
        std::size_t hidden_items = 0;  // work items hierarchical-Z culling skipped
    };
    FillCounts counts() const;
    // After a fill: the counters of that fill are copied aside, to be read a frame later
    // without waiting (previous).
    void keep_count();
    // The counters kept by the last keep_count (records appended = vertex_count / 6). Read
    // back once per keep_count: the passes of a frame that ask again get the same copy.
    EdgeDrawCommand previous() const;
    // Whether keep_count ran yet: before it, previous() knows nothing of the scene's size.
    bool has_previous() const { return has_previous_; }
    // The kept counts no longer describe the frame before (it was drawn without the edge
    // buffer, LineMethod::automatic): back to the first frame's state, so the next fill sizes
    // itself from its own counts (edges_sized) instead of from an older frame's.
    void forget_previous();

    // The frame's edge-extraction work (render/lines/edge_culling.h, binding kEdgeWorkBinding):
    // each instance's object-space eye, then the work items.
    void set_work(std::span<const glm::uvec4> work);
    const gl::Buffer& work() const { return work_; }

    std::uint32_t capacity() const { return capacity_; }
    std::uint32_t max_capacity() const { return max_capacity_; }
    std::uint32_t sample_capacity() const { return sample_capacity_; }
    const gl::Buffer& records() const { return records_; }
    const gl::Buffer& command() const { return command_; }
    const gl::Buffer& samples() const { return samples_; }
    const gl::Buffer& spans() const { return spans_; }
    // A vertex array with no attributes whose element buffer indexes every record's quad:
    // record k's corners 4k .. 4k + 3 as two triangles (0 1 2, 2 1 3), for capacity() records.
    const gl::VertexArray& quad_indices() const { return quad_vao_; }

  private:
    EdgeDrawCommand read_now() const;

    gl::Buffer records_;
    gl::Buffer command_;
    gl::Buffer kept_count_;
    gl::Buffer readback_;  // counts() reads the counters from here
    gl::Buffer work_;
    gl::Buffer samples_;  // one uint per spine sample: 1 visible, 0 hidden
    gl::Buffer
        spans_;  // per record: 2 uvec4, sampled stretch, first and last visible sample, count
    gl::Buffer quad_index_buffer_;
    gl::VertexArray quad_vao_;
    std::uint32_t capacity_ = 0;
    std::uint32_t max_capacity_ = 0;
    std::uint32_t sample_capacity_ = 0;
    std::uint32_t max_samples_ = 0;
    bool has_previous_ = false;
    mutable std::optional<EdgeDrawCommand> previous_;  // kept_count_ as read back
};

}  // namespace bz::render
