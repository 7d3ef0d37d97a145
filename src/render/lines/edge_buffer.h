#pragma once
// The edge buffer: every visible feature edge of a frame, one record each, written by the
// edge-extraction compute shader (LineMethod::compute, shaders/lines/edges.comp) and read by the
// line vertex shader that draws one quad per record (shaders/lines/edge_quad.vert). It is the
// substrate styles build on (strokes, jitter, chaining, smoothing): one record carries everything a
// stroke needs about its edge without going back to the mesh.
//
// The GLSL side is shaders/lines/edge_record.glsl; the two must stay byte-identical (std430, a
// static_assert below pins the size and offsets). All vectors are view space (camera at the
// origin, looking down -z) unless they say window pixels.
//
// Reconstructing a view-space end point from the record: with the ray through window position
// px, r = ((px / viewport) * 2 - 1) / (P[0][0], P[1][1]) extended by z = -1 (u_ray in
// pass_lines.cpp), the point is r / inv_depth.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "gl/indirect_commands.h"

namespace bz::render {

// What made an edge a feature edge (EdgeRecord::kind_flags bits 0-3).
enum class EdgeKindCode : std::uint32_t {
    crease = 0,  // both faces on the same side of the eye and the dihedral angle past the threshold
    silhouette = 1,  // one face towards the eye, the other away
    boundary = 2,    // one face only, or non-manifold / inconsistently wound: always drawn
};

// EdgeRecord::kind_flags bits above the kind.
namespace edge_flags {
inline constexpr std::uint32_t kind_mask = 0xFu;
inline constexpr std::uint32_t face_a_front = 1u << 4;  // face A faces the eye
inline constexpr std::uint32_t face_b_front = 1u << 5;  // face B exists and faces the eye
inline constexpr std::uint32_t has_face_b = 1u << 6;    // the edge has a second (consistent) face
inline constexpr std::uint32_t non_manifold = 1u << 7;  // 3+ faces share it (one record per face)
inline constexpr std::uint32_t inconsistent = 1u << 8;  // the two faces are wound the opposite way
inline constexpr std::uint32_t clipped_start = 1u
                                               << 9;  // end a was moved by near/far/guard clipping
inline constexpr std::uint32_t clipped_end = 1u << 10;  // end b was moved
// A crease record drawn only because its faces have different materials (material lines on).
inline constexpr std::uint32_t material = 1u << 11;
// A crease record that is no mesh edge but where two surfaces cross (intersection lines on:
// shaders/lines/intersections.comp); its vertex ids are the segment's own.
inline constexpr std::uint32_t intersection = 1u << 12;
}  // namespace edge_flags

// One visible feature edge, 176 bytes (std430: 11 x 16). "a -> b" is the edge's direction:
// for a silhouette, the front face's winding; for a crease, from the lower to the higher welded
// vertex; for a boundary-like edge, its one face's winding. Face A is the face that runs a -> b
// (always present); face B the one across the edge (may be absent).
struct EdgeRecord {
    glm::vec4 screen;      // xy: end a, zw: end b, window pixels, after clipping (the spine)
    glm::vec4 depth;       // x, y: 1 / view depth at a and b (affine along the screen spine);
                           // z, w: where a and b lie on the unclipped edge (0..1 parameter),
                           // for stroke parameterisation across clipped ends
    glm::vec4 edge_plane;  // xyz: plane through the eye and the unclipped edge, oriented so
                           // that face A is on its positive side; w: dihedral cosine of the
                           // two faces (object space, 2.0 when there is no face B): the
                           // edge's significance, -1 sharpest .. 1 flat
    glm::vec4 face_pos;    // xyz: the spine test's plane for the positive side (n / (n.p),
                           // see shaders/lines/spine_test.glsl); zero = use the spine's depth; w: 0
    glm::vec4 face_neg;    // xyz: ... for the negative side; w: 0
    // The four normals are written only where the frame's strokes read them
    // (records_carry_normals, passes.h): elsewhere they hold what the buffer held.
    glm::vec4 normal_a;         // xyz: unit normal of face A; w: 0
    glm::vec4 normal_b;         // xyz: unit normal of face B, zero when absent; w: 0
    glm::vec4 vertex_normal_a;  // xyz: unit smooth (angle-weighted) vertex normal at a; w: 0
    glm::vec4 vertex_normal_b;  // xyz: ... at b; w: 0
    glm::uvec4 ids;             // x: kind_flags (EdgeKindCode | edge_flags); y: instance index
                     // in this frame's instance buffer (InstanceData: colour, model-view;
                     // not stable across frames); z: edge id, stable index into the
                     // mesh's edge list (for per-edge seeds); w: the scene::MeshId
    glm::uvec4 vertices;  // x, y: welded vertex ids of a and b in the mesh (for chaining
                          // edges into strokes: records sharing a vertex id and instance
                          // meet); z: the record's first spine sample in the sample
                          // buffer, w: its sample count (0: none; spine_samples.glsl)
};
static_assert(sizeof(EdgeRecord) == 176, "must match shaders/lines/edge_record.glsl (std430)");
static_assert(offsetof(EdgeRecord, ids) == 144,
              "must match shaders/lines/edge_record.glsl (std430)");

// The buffer's header, at offset 0 of the edge buffer's indirect-draw buffer: the
// DrawArraysIndirectCommand the quad pass draws with. The compute shader appends a record by
// atomically adding kVerticesPerEdge to vertex_count, so the count needs no fix-up pass:
// edges appended = vertex_count / kVerticesPerEdge (capped at the buffer's capacity).
// After it, the spine-sample append counter.
struct DrawArraysCommand {
    std::uint32_t count = 0;
    std::uint32_t instance_count = 1;
    std::uint32_t first = 0;
    std::uint32_t base_instance = 0;
};
struct EdgeDrawCommand {
    std::uint32_t vertex_count = 0;
    std::uint32_t instance_count = 1;
    std::uint32_t first_vertex = 0;
    std::uint32_t base_instance = 0;
    std::uint32_t samples_used = 0;  // spine samples asked for, including any past capacity
    std::uint32_t hidden_items = 0;  // work items hierarchical-Z culling skipped (hiz_culling.h)
    // Written by spine_visibility.comp, read as the quad pass's two indexed indirect draws:
    // the records with spine samples (the frame's samples fit) and those whose fragments run
    // the spine test (they did not); one of the two draws nothing (pass_edge_quads.cpp). Their
    // counts stop at the buffer's capacity, where the quad indices end. Each draws through
    // EdgeStorage::quad_indices: a quad's four corners indexed by its two triangles, so the
    // vertex shader runs four times per quad, not six (on llvmpipe, one thread runs every
    // vertex: 0.8-1 ms of the seed's hallway).
    gl::DrawElementsIndirectCommand sampled_draw;
    gl::DrawElementsIndirectCommand tested_draw;
};
static_assert(offsetof(EdgeDrawCommand, sampled_draw) == 24 &&
                  offsetof(EdgeDrawCommand, tested_draw) == 44 && sizeof(EdgeDrawCommand) == 64,
              "must match shaders/lines/edge_record.glsl (EDGE_COMMAND_MEMBERS)");
inline constexpr std::uint32_t kVerticesPerEdge = 6;  // two triangles per quad, unindexed
inline constexpr std::uint32_t kCornersPerEdge = 4;   // indexed (EdgeStorage::quad_indices)

// Binding points of the edge-extraction and quad programs (shaders/lines/edge_record.glsl).
inline constexpr unsigned kEdgeListBinding = 2;       // the mesh's MeshEdge list
inline constexpr unsigned kEdgePositionsBinding = 3;  // the mesh's positions (vec3 as 3 floats)
inline constexpr unsigned kEdgeRecordsBinding = 4;    // EdgeRecord[] (written, then read)
inline constexpr unsigned kEdgeCommandBinding = 5;    // EdgeDrawCommand (atomic counter)
inline constexpr unsigned kVertexNormalsBinding = 6;  // the mesh's vertex normals (3 floats each)
inline constexpr unsigned kSpineSamplesBinding = 7;   // one visibility word per spine sample
inline constexpr unsigned kSpineSpansBinding = 8;     // per record: first and last visible sample
inline constexpr unsigned kFaceNormalsBinding = 9;    // the mesh's face normals (geo::face_normals)
inline constexpr unsigned kEdgeWorkBinding = 10;      // eyes and work items (edge_culling.h)
// The frame's intersection segments (intersections.comp; render/lines/intersection_records.h).
inline constexpr unsigned kIntersectionsBinding = 12;

}  // namespace bz::render
