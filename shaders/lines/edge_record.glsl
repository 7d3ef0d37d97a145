// The edge buffer's record, byte for byte the C++ render::EdgeRecord (src/render/lines/edge_buffer.h,
// which documents every field). Written by shaders/lines/edges.comp, read by shaders/lines/edge_quad.vert
// and by any style that strokes the frame's feature edges.
struct EdgeRecord {
    vec4 screen;           // xy: end a, zw: end b (window pixels, clipped)
    vec4 depth;            // x, y: 1 / view depth at a, b; z, w: their parameters on the unclipped edge
    vec4 edge_plane;       // xyz: eye-edge plane, face A positive; w: dihedral cosine (2: no face B)
    vec4 face_pos;         // xyz: spine-test plane on the positive side (0: spine depth)
    vec4 face_neg;         // xyz: ... negative side
    vec4 normal_a;         // xyz: unit view-space normal of face A
    vec4 normal_b;         // xyz: ... of face B (0: none)
    vec4 vertex_normal_a;  // xyz: unit view-space smooth vertex normal at a
    vec4 vertex_normal_b;  // xyz: ... at b
    uvec4 ids;             // x: kind | flags, y: instance index, z: edge id in the mesh, w: mesh id
    uvec4 vertices;        // x, y: welded vertex ids of a and b; z: first spine sample, w: samples
};

const uint EDGE_CREASE = 0u;
const uint EDGE_SILHOUETTE = 1u;
const uint EDGE_BOUNDARY = 2u;
const uint EDGE_KIND_MASK = 0xFu;
const uint EDGE_FACE_A_FRONT = 1u << 4;
const uint EDGE_FACE_B_FRONT = 1u << 5;
const uint EDGE_HAS_FACE_B = 1u << 6;
const uint EDGE_NON_MANIFOLD = 1u << 7;
const uint EDGE_INCONSISTENT = 1u << 8;
const uint EDGE_CLIPPED_START = 1u << 9;
const uint EDGE_CLIPPED_END = 1u << 10;
const uint EDGE_MATERIAL = 1u << 11;
const uint EDGE_INTERSECTION = 1u << 12;

// The DrawArraysIndirectCommand of the quad draw; vertex_count doubles as the append counter
// (EDGE_VERTICES per record). Then the spine-sample append counter and the count of work items
// hierarchical-Z culling skipped (render::EdgeDrawCommand). Then the two quad draws
// spine_visibility.comp writes: the records with spine samples, and the records tested per
// fragment (each a DrawElementsIndirectCommand over the quads' corner indices, EDGE_CORNERS
// per record, of which it sets the count and instance count; the rest stay 0).
// A shader declares the block as `buffer Command { EDGE_COMMAND_MEMBERS; };`.
#define EDGE_COMMAND_MEMBERS \
    uint vertex_count;       \
    uint instance_count;     \
    uint first_vertex;       \
    uint base_instance;      \
    uint samples_used;       \
    uint hidden_items;       \
    uint sampled_draw_count; \
    uint sampled_draw_instances; \
    uint sampled_draw_first_index; \
    uint sampled_draw_base_vertex; \
    uint sampled_draw_base_instance; \
    uint tested_draw_count;  \
    uint tested_draw_instances; \
    uint tested_draw_first_index; \
    uint tested_draw_base_vertex; \
    uint tested_draw_base_instance
const uint EDGE_VERTICES = 6u;  // per record: two triangles, unindexed
const uint EDGE_CORNERS = 4u;   // per record: the indexed draws' distinct vertices

// The binding points (EDGE_LIST_BINDING, EDGE_RECORDS_BINDING, ...) are #defines injected from
// src/render/lines/edge_buffer.h (src/render/shader_interface.h).
