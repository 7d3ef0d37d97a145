#pragma once
// A bounding-volume hierarchy over triangles in double precision, answering one question for
// the CPU reference: does a segment hit any triangle (other than an excluded edge's faces)?
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace bz::geo::detail {

struct BvhTriangle {
    glm::dvec3 p0{0.0}, p1{0.0}, p2{0.0};
    std::uint32_t instance = 0;
    std::uint32_t v0 = 0, v1 = 0, v2 = 0;  // welded vertex ids within the instance's mesh
};

// One triangle of one instance, by its welded vertex ids in the mesh's order.
struct ExcludedFace {
    std::uint32_t instance = ~0u;
    std::uint32_t v0 = ~0u, v1 = ~0u, v2 = ~0u;
};

// Triangles that hold both vertices of this edge, in this instance, are skipped, and so are
// the faces named (an intersection line's two faces: it lies on both).
struct ExcludedEdge {
    std::uint32_t instance = ~0u;
    std::uint32_t va = ~0u;
    std::uint32_t vb = ~0u;
    ExcludedFace faces[2];
};

class TriangleBvh {
  public:
    explicit TriangleBvh(std::vector<BvhTriangle> triangles);

    // True if origin + t * dir hits a non-excluded triangle for some t in [t_min, t_max].
    // Hits on a triangle's edges and corners count (rays through a shared edge never leak).
    bool any_hit(const glm::dvec3& origin, const glm::dvec3& dir, double t_min, double t_max,
                 const ExcludedEdge& excluded) const;

    // How many surfaces facing the origin the segment crosses for t in [t_min, t_max]: hits on
    // non-excluded triangles that face the origin, those at the same t (a ray through a shared
    // edge or corner) counted once. Stops counting at `cap`.
    int count_front_hits(const glm::dvec3& origin, const glm::dvec3& dir, double t_min,
                         double t_max, const ExcludedEdge& excluded, int cap) const;

    std::size_t size() const { return triangles_.size(); }

  private:
    struct Node {
        glm::dvec3 lo{0.0}, hi{0.0};
        std::uint32_t first = 0;  // leaf: first triangle; inner: right child (left is next)
        std::uint32_t count = 0;  // 0 for inner nodes
    };
    std::uint32_t build(std::uint32_t first, std::uint32_t count, int depth);

    std::vector<BvhTriangle> triangles_;
    std::vector<Node> nodes_;
};

// Möller-Trumbore in double; t of the hit or a negative value for a miss.
double intersect(const BvhTriangle& tri, const glm::dvec3& origin, const glm::dvec3& dir);

}  // namespace bz::geo::detail
