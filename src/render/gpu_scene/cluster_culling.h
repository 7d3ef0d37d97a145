#pragma once
// Tests of one instance's clusters (geometry/derived/cluster_bounds.h) against the view, on
// the CPU, before any per-element work: outside a view volume, and facing. The edge pass
// (render/lines/edge_culling.h) and the triangle passes (triangle_culling.h) share them.
#include <cstddef>
#include <glm/glm.hpp>

#include "geometry/derived/cluster_bounds.h"

namespace bz::render {

// The edge and triangle passes cull on more threads from this many (instance, cluster)
// pairs: below it a thread's start costs more than its share of the work.
inline constexpr std::size_t kCullPairsPerThread = 16384;

// The eye in the instance's object space (xyz) and the sign of det(model_view) (w): a face
// with object-space normal n and vertex p faces the eye when w * dot(n, xyz - p) > 0, exactly
// when its view-space normal faces the view-space origin. w is 0 for a singular model-view
// (no face then faces the eye, as in view space, where every normal is zero).
glm::vec4 object_space_eye(const glm::mat4& model_view);

// The largest length the linear part of `m` gives a unit axis: what it scales a bounding
// sphere's radius by, at most.
double max_axis_scale(const glm::dmat3& m);

// The side planes of the view frustum widened `guard` times (|x|, |y| <= guard * w in clip
// space), and the near and far depths, in view space.
class ViewVolume {
  public:
    ViewVolume(const glm::mat4& proj, float near, float far, double guard);
    // Whether a view-space sphere lies wholly outside, or wholly inside.
    bool outside(const glm::dvec3& center, double radius) const;
    bool contains(const glm::dvec3& center, double radius) const;

  private:
    glm::dvec4 planes_[4];  // unit normals: inside where dot(xyz, p) + w >= 0
    double near_, far_;
};

enum class ClusterFacing { mixed, all_front, all_back };

// A sphere in view space.
struct ViewSphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// One instance's view of its clusters.
class InstanceClusters {
  public:
    explicit InstanceClusters(const glm::mat4& model_view);
    // The cluster's bounding sphere in view space (widened for rounding, as the tests use it).
    ViewSphere view_sphere(const geo::ClusterBounds& k) const;
    bool outside(const geo::ClusterBounds& k, const ViewVolume& volume) const;
    // Whether the sphere lies wholly inside: then none of the clusters it holds is outside.
    bool inside(const geo::ClusterBounds& k, const ViewVolume& volume) const;
    // Whether every face of the cluster faces the eye, or every one faces away, with a margin
    // far above the float rounding of a shader's facing test; mixed when unsure.
    ClusterFacing facing(const geo::ClusterBounds& k) const;

  private:
    glm::dmat4 model_view_;
    double scale_;    // the largest axis scale of the model-view (sphere radii)
    glm::dvec3 eye_;  // object_space_eye
    double eye_sign_;
};

}  // namespace bz::render
