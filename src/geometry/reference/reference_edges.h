#pragma once
// Feature-edge finding for the CPU reference: the geometry shader's rules (lines.geom) in
// double precision, per instance.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/reference/reference.h"
#include "geometry/reference/reference_bvh.h"

namespace bz::geo::detail {

using FeatureKind = LineKind;

struct FeatureEdge {
    glm::dvec3 a{0.0};  // view space
    glm::dvec3 b{0.0};
    std::uint32_t instance = 0;
    std::uint32_t va = 0;  // welded vertex ids: the faces holding both are the edge's own
    std::uint32_t vb = 0;
    FeatureKind kind = FeatureKind::crease;
    // An intersection line's two faces (it lies on both, so neither hides it); none for an
    // edge, whose faces are those holding va and vb.
    ExcludedFace faces[2];
};

// Appends the feature edges of one instance. `view_positions` are the mesh's positions
// transformed by the instance's model-view matrix. Non-interior edges shared by several faces
// are reported once.
void find_feature_edges(const ReferenceInstance& instance, std::uint32_t instance_index,
                        const std::vector<glm::dvec3>& view_positions,
                        std::vector<FeatureEdge>& out);

// Appends the intersection lines of the occluding instances (ReferenceOptions::
// intersection_lines), in view space.
void find_intersection_edges(std::span<const ReferenceInstance> instances,
                             std::vector<FeatureEdge>& out);

}  // namespace bz::geo::detail
