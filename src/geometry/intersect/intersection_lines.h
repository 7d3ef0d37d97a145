#pragma once
// Intersection lines: where the surfaces of two objects (or two non-adjacent faces of one)
// cross, the crossing is a line. The exact reference and the renderer both take their
// segments from here, so the two draw the same lines.
//
// A PlacedMesh is a mesh's triangles brought into one space (view space for the reference,
// world space for the renderer, which caches each pair's segments until one of the two moves
// or changes mesh: render/gpu_scene/intersection_cache.h). The broad phase is the placed
// meshes' bounds, then a uniform grid over the triangles of one mesh inside the overlap of the
// two bounds; the narrow phase is triangle_crossing.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

struct DBox {
    glm::dvec3 lo{0.0};
    glm::dvec3 hi{-1.0};  // empty
    bool empty() const { return hi.x < lo.x || hi.y < lo.y || hi.z < lo.z; }
    bool overlaps(const DBox& o) const {
        return !empty() && !o.empty() && lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y &&
               o.lo.y <= hi.y && lo.z <= o.hi.z && o.lo.z <= hi.z;
    }
};

// A uniform grid over a placed mesh's bounds, about one cell per triangle, each cell listing
// the triangles whose bounds meet it (cell c's are items[first[c] .. first[c + 1])). Built
// once per placement, so that a pair asks only about the triangles near the other mesh: a
// large sparse mesh (a skyline ring around the eye, whose bounds hold the whole field) costs
// a pair nothing where none of its triangles lies.
struct TriangleGridIndex {
    glm::dvec3 lo{0.0};
    glm::dvec3 cell{1.0};
    glm::ivec3 dims{0};
    std::vector<std::uint32_t> first;
    std::vector<std::uint32_t> items;
};

struct PlacedMesh {
    const AdjacencyMesh* mesh = nullptr;
    std::vector<glm::dvec3> positions;  // the mesh's positions, transformed
    std::vector<DBox> triangle_bounds;  // one per triangle
    DBox bounds;
    TriangleGridIndex grid;
};

PlacedMesh place_mesh(const AdjacencyMesh& mesh, const glm::dmat4& transform);

// One crossing: the segment a-b lies on triangle `triangle_a` of the first mesh and
// `triangle_b` of the second (triangle indices into AdjacencyMesh::triangles / 3).
struct IntersectionSegment {
    glm::dvec3 a{0.0};
    glm::dvec3 b{0.0};
    std::uint32_t triangle_a = 0;
    std::uint32_t triangle_b = 0;
};

// Where the surfaces of two different placed meshes cross.
std::vector<IntersectionSegment> pair_intersections(const PlacedMesh& first,
                                                    const PlacedMesh& second);

// Where non-adjacent triangles of one placed mesh (sharing no welded vertex) cross; each
// crossing once, with triangle_a < triangle_b.
std::vector<IntersectionSegment> self_intersections(const PlacedMesh& mesh);

// A segment of a scene: which placed meshes (indices into the span given) it lies on.
struct SceneIntersection {
    IntersectionSegment segment;
    std::uint32_t first = 0;  // first <= second; equal for a mesh's own crossing
    std::uint32_t second = 0;
};

// Every crossing of a scene: each pair of meshes whose bounds overlap, and each mesh with
// itself.
std::vector<SceneIntersection> scene_intersections(std::span<const PlacedMesh> meshes);

}  // namespace bz::geo
