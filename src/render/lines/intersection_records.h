#pragma once
// A frame's intersection lines as the GPU takes them (shaders/lines/intersections.comp): the
// cached world-space segments (render/gpu_scene/intersection_cache.h) brought into view space
// in double, for the instances the frame draws.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "render/gpu_scene/batches.h"
#include "render/gpu_scene/intersection_cache.h"

namespace bz::render {

// std430, byte for byte intersections.comp's `Intersection`.
struct IntersectionRecord {
    glm::vec4 a{0.0f};         // xyz: end a, view space
    glm::vec4 b{0.0f};         // xyz: end b
    glm::vec4 normal_a{0.0f};  // xyz: unit view-space normal of the first face
    glm::vec4 normal_b{0.0f};  // xyz: ... of the second
    glm::uvec4 ids{0u};        // x: instance (colour, beam), y: stable id, z: mesh id
};
static_assert(sizeof(IntersectionRecord) == 80, "must match shaders/lines/intersections.comp");

// The segments whose two objects the frame draws at full detail: one drawn from its
// simplified mesh (distance LOD) has another surface in the prepass, so its crossings are
// left out, as the reference leaves them out when it mirrors the LOD. The record takes the
// first object's colour. `instance_of_item`: FrameBatches::instance_of_item.
std::vector<IntersectionRecord> intersection_records(std::span<const WorldIntersection> segments,
                                                     const FrameBatches& batches,
                                                     const std::vector<scene::DrawItem>& items,
                                                     const glm::dmat4& view);

}  // namespace bz::render
