#pragma once
// Intersection lines for the renderer: the crossings of the frame's occluders (and of each
// one's own non-adjacent faces), computed on the CPU by geometry/intersect/ (the code the
// exact reference uses) and kept from frame to frame.
//
// The cache is keyed by what decides the segments: a placement is a mesh (id and version) at
// one model matrix. A pair of placements whose world bounds overlap is computed when it is
// first seen and kept while both placements are in the frame, so static scenery is computed
// once, and an object that moves (a new model matrix) or changes mesh recomputes only its own
// pairs. A mesh's own crossings do not depend on where it stands: once per mesh version.
#include <chrono>
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <unordered_map>
#include <vector>

#include "geometry/intersect/intersection_lines.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::render {

// One intersection line of a frame, in world space: it lies on a face of item `first` and one
// of item `second` (indices into the frame's items; equal for an object's own crossing).
struct WorldIntersection {
    glm::dvec3 a{0.0}, b{0.0};
    glm::dvec3 normal_first{0.0}, normal_second{0.0};  // unit world normals of the two faces
    std::uint32_t first = 0, second = 0;
    std::uint32_t id = 0;  // stable while the pair stays cached (per-edge seeds)
};

struct IntersectionStats {
    std::size_t placements = 0;       // occluders taking part
    std::size_t pairs = 0;            // pairs whose bounds overlap
    std::size_t pairs_computed = 0;   // of those, computed this frame (new or moved)
    std::size_t meshes_computed = 0;  // meshes whose own crossings were computed this frame
    std::size_t segments = 0;
    double update_ms = 0.0;  // CPU time of update()
};

class IntersectionCache {
  public:
    IntersectionCache();
    ~IntersectionCache();
    IntersectionCache(IntersectionCache&&) noexcept;
    IntersectionCache& operator=(IntersectionCache&&) noexcept;

    // Brings the segments up to date with `items` (only occluders take part: the GPU tests
    // visibility against the depth prepass, which holds nothing else) and forgets every pair
    // and placement the frame no longer has.
    const std::vector<WorldIntersection>& update(const std::vector<scene::DrawItem>& items,
                                                 const scene::MeshLibrary& meshes);
    const std::vector<WorldIntersection>& segments() const { return segments_; }
    const IntersectionStats& stats() const { return stats_; }

  private:
    struct State;
    std::unique_ptr<State> state_;
    std::vector<WorldIntersection> segments_;
    IntersectionStats stats_;
};

}  // namespace bz::render
