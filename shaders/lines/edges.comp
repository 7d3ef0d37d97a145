#version 450 core
// Edge extraction (LineMethod::compute): one work group per work item, one invocation per edge
// of the item's stretch of the mesh's clustered edge list (geo::cluster_edges). The CPU has
// already dropped the clusters that cannot give a feature edge (render/lines/edge_culling.h).
// It classifies the edge with the geometry shader's definitions (shaders/lines/lines.geom:
// facing, the crease threshold, back faces skipped for outward-closed meshes seen from
// outside), clips it with the same code, and appends each visible feature edge to the edge
// buffer (edge_record.glsl). Facing is tested in object space, against the eye brought into
// the instance's space once per frame and the mesh's precomputed face normals, so an edge that
// is no feature costs no vertex transform; only feature edges go to view space. Each edge is
// tested once instead of once from each of its faces, and the work is spread over every
// thread llvmpipe (or a GPU) has.
#include "edge_record.glsl"
#include "spine_samples.glsl"

// EDGE_GROUP_SIZE invocations per work group (programs.cpp: 64 on a GPU, 8 on llvmpipe, where
// every invocation costs a start-up of its own), each looping over its item's edges.
#ifndef EDGE_GROUP_SIZE
#define EDGE_GROUP_SIZE 64
#endif
layout(local_size_x = EDGE_GROUP_SIZE) in;

struct MeshEdge {
    uint a, b;        // in face A's winding
    uint opp_a;       // face A's third vertex
    uint opp_b;       // face B's third vertex, 0xFFFFFFFF without face B
    float cos_dihedral;
    uint flags;       // 0 interior, 1 boundary, 2 non-manifold, 3 inconsistent; | 16 material
    uint face_a;      // face A's triangle, into face_normals
    uint face_b;      // face B's triangle, 0xFFFFFFFF without face B
    uint id;          // stable id for per-edge seeds (the list's order before clustering)
};
layout(std430, binding = EDGE_LIST_BINDING) readonly buffer Edges { MeshEdge edges[]; };
layout(std430, binding = EDGE_POSITIONS_BINDING) readonly buffer Positions { float positions[]; };
layout(std430, binding = EDGE_VERTEX_NORMALS_BINDING) readonly buffer VertexNormals { float vertex_normals[]; };
// Per triangle, its unnormalised object-space normal (geo::face_normals).
layout(std430, binding = EDGE_FACE_NORMALS_BINDING) readonly buffer FaceNormals { vec4 face_normals[]; };
// Per instance of the frame, its object-space eye (xyz) and the sign of det(model-view) (w) as
// float bits; then the work items: x instance, y first edge, z edge count.
layout(std430, binding = EDGE_WORK_BINDING) readonly buffer Work { uvec4 work[]; };
// render::InstanceData: the model-view and the parameters (x: cos(crease angle)).
#include "../instance_data.glsl"
layout(std430, binding = EDGE_RECORDS_BINDING) writeonly buffer Records { EdgeRecord records[]; };
// Per record, two entries: the sampled stretch and the visible one, then the visible count
// (spine_samples.glsl).
layout(std430, binding = SPINE_SPANS_BINDING) writeonly buffer Spans { uvec4 spans[]; };
layout(std430, binding = EDGE_COMMAND_BINDING) buffer Command { EDGE_COMMAND_MEMBERS; };

uniform uint u_work_base;       // this dispatch's first work item in `work`
uniform uint u_work_end;        // one past its last
uniform uint u_capacity;        // records the buffer holds; later appends are counted, not written
uniform uint u_sample_capacity; // spine samples the sample buffer holds (0: none wanted)
uniform float u_sample_margin;  // pixels around the viewport that spine samples cover
uniform float u_sample_spacing; // pixels between spine samples
uniform uint u_mesh_id;
uniform bool u_skip_back_faces;
// Draw material boundaries (MeshEdge flag 16, geo::kEdgeMaterialBoundary) as lines; set only
// for a mesh that has them.
uniform bool u_material_lines;
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;
// Hierarchical-Z culling (src/render/lines/hiz_culling.h): the farthest surface's inverse view
// depth per fine and per coarse tile, and where each item's bounds record lies in `work`.
layout(binding = TEXTURE_UNIT_DEPTH_TILES) uniform sampler2D u_depth_tiles;
layout(binding = TEXTURE_UNIT_DEPTH_TILES_COARSE) uniform sampler2D u_depth_tiles_coarse;
uniform bool u_hiz;
uniform uint u_bounds_offset;  // an item's record is work[u_bounds_offset + its index]
uniform float u_hiz_rel;       // the spine test's tolerances, with room to spare
uniform float u_hiz_abs;

#include "edge_geometry.glsl"

const uint kNoVertex = 0xFFFFFFFFu;
const uint kEdgeMaterialBoundary = 16u;  // geo::kEdgeMaterialBoundary

vec3 position(uint v) { return vec3(positions[3u * v], positions[3u * v + 1u], positions[3u * v + 2u]); }
vec3 vertex_normal(uint v) {
    return vec3(vertex_normals[3u * v], vertex_normals[3u * v + 1u], vertex_normals[3u * v + 2u]);
}
vec3 unit_or_zero(vec3 v) { float l = length(v); return l > 0.0 ? v / l : vec3(0.0); }

// The stretch (t0, t1) of the spine s0-s1 within the viewport grown by u_sample_margin
// (Liang-Barsky); t0 > t1 when none of it is. Spine points farther out light no pixel.
vec2 on_screen_stretch(vec2 s0, vec2 s1) {
    vec2 lo = vec2(-u_sample_margin), hi = u_viewport + u_sample_margin;
    vec2 d = s1 - s0;
    float t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        if (abs(d[axis]) < 1e-6) {
            if (s0[axis] < lo[axis] || s0[axis] > hi[axis]) return vec2(1.0, 0.0);
            continue;
        }
        float ta = (lo[axis] - s0[axis]) / d[axis], tb = (hi[axis] - s0[axis]) / d[axis];
        t0 = max(t0, min(ta, tb));
        t1 = min(t1, max(ta, tb));
    }
    return vec2(t0, t1);
}

mat4 model_view(uint inst) { return instance_model_view(inst); }

// Whether a face faces the eye: in object space (normal n, eye minus its vertex a), with the
// view-space test of the geometry shader for a near tie, so that both line methods classify a
// grazing face alike (the object-space rounding differs from the view-space one, and the
// difference showed as a few lost silhouette pixels against the exact reference). The face is
// a, v1, v2 in its winding, here in view space; `det_sign` is the instance's (the eye's w).
bool faces_eye_resolved(float det_sign, vec3 n, vec3 to_eye, vec3 a, vec3 v1, vec3 v2) {
    float s = det_sign * dot(n, to_eye);
    if (abs(s) > 1e-4 * length(n) * length(to_eye)) return s > 0.0;
    return faces_eye(face_normal(a, v1, v2), a);
}

// The edge's vertices in view space: a and b, and the third vertices of faces A and B (zero
// without face B).
struct ViewVertices {
    mat4 mv;
    vec3 a, b, opp_a, opp_b;
};
ViewVertices view_vertices(uint inst, MeshEdge me, vec3 pa, bool has_b) {
    ViewVertices v;
    v.mv = model_view(inst);
    v.a = (v.mv * vec4(pa, 1.0)).xyz;
    v.b = (v.mv * vec4(position(me.b), 1.0)).xyz;
    v.opp_a = (v.mv * vec4(position(me.opp_a), 1.0)).xyz;
    v.opp_b = has_b ? (v.mv * vec4(position(me.opp_b), 1.0)).xyz : vec3(0.0);
    return v;
}

#ifndef EDGE_WORK_LISTED
// faces_eye_resolved with the face's vertices in object space, transformed only for a tie.
bool faces_eye_object(uint inst, float det_sign, vec3 n, vec3 to_eye, vec3 pa, uint v1, uint v2) {
    float s = det_sign * dot(n, to_eye);
    if (abs(s) > 1e-4 * length(n) * length(to_eye)) return s > 0.0;
    mat4 mv = model_view(inst);
    vec3 a = (mv * vec4(pa, 1.0)).xyz;
    return faces_eye_resolved(det_sign, n, to_eye, a, (mv * vec4(position(v1), 1.0)).xyz,
                              (mv * vec4(position(v2), 1.0)).xyz);
}
#endif

// Whether every tile under the item's rectangle holds a surface nearer than the nearest point
// of its bounding sphere, by more than the spine test would forgive: then no spine sample of
// any of its edges can pass. Every invocation of the group reads the same record and tiles,
// so the whole group returns together (listed work: each invocation reads its entry's
// cluster's record).
bool hidden_by_prepass(uint item_index) {
    uvec4 b = work[u_bounds_offset + item_index];
    if (b.w == 0u) return false;
    ivec2 lo = ivec2(b.x & 0xFFFFu, b.x >> 16), hi = ivec2(b.y & 0xFFFFu, b.y >> 16);
    float limit = uintBitsToFloat(b.z) * (1.0 + u_hiz_rel) + u_hiz_abs;
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            float farthest = b.w == 1u ? texelFetch(u_depth_tiles, ivec2(x, y), 0).r
                                       : texelFetch(u_depth_tiles_coarse, ivec2(x, y), 0).r;
            if (!(farthest > limit)) return false;
        }
    }
    return true;
}

// Classifies edge e of instance inst (its object-space eye `eye`) and appends it when it is a
// visible feature edge.
void test_edge(uint inst, vec4 eye, uint e) {
    MeshEdge me = edges[e];
    vec3 pa = position(me.a);
    vec3 to_eye = eye.xyz - pa;  // both faces hold vertex a
    vec3 obj_na = face_normals[me.face_a].xyz;
    bool has_b = me.opp_b != kNoVertex && me.face_b != kNoVertex;
    vec3 obj_nb = has_b ? face_normals[me.face_b].xyz : vec3(0.0);
#ifdef EDGE_WORK_LISTED
    // Listed edges are nearly all feature edges (the CPU prefilter dropped the rest), and
    // llvmpipe runs every branch whether a lane takes it or not: the view-space vertices are
    // computed once, up front, instead of once for each face's tie test and again below.
    ViewVertices v = view_vertices(inst, me, pa, has_b);
    bool front_a = faces_eye_resolved(eye.w, obj_na, to_eye, v.a, v.b, v.opp_a);
#else
    bool front_a = faces_eye_object(inst, eye.w, obj_na, to_eye, pa, me.b, me.opp_a);
#endif

    // The geometry shader's cases, seen from the edge instead of from each face; everything
    // that is no feature edge returns before any vertex is transformed (a tie aside).
    uint kind;
    uint flags = front_a ? EDGE_FACE_A_FRONT : 0u;
    bool front_b = false;
    if (!has_b) {
        // Boundary, non-manifold or inconsistent: always a feature edge, one record per face.
        if (!front_a && u_skip_back_faces) return;
        kind = EDGE_BOUNDARY;
        if (me.flags == 2u) flags |= EDGE_NON_MANIFOLD;
        if (me.flags == 3u) flags |= EDGE_INCONSISTENT;
    } else {
#ifdef EDGE_WORK_LISTED
        front_b = faces_eye_resolved(eye.w, obj_nb, to_eye, v.a, v.opp_b, v.b);
#else
        front_b = faces_eye_object(inst, eye.w, obj_nb, to_eye, pa, me.opp_b, me.b);
#endif
        flags |= EDGE_HAS_FACE_B | (front_b ? EDGE_FACE_B_FRONT : 0u);
        if (front_a != front_b) {
            kind = EDGE_SILHOUETTE;
        } else {
            if (!front_a && u_skip_back_faces) return;
            float cos_crease = instance_params(inst).x;
            if (!(me.cos_dihedral < cos_crease)) {
                // Not a crease: still a line as a material boundary, with the geometry
                // shader's rule (none for an object past the creases' distance LOD).
                if (!(u_material_lines && cos_crease >= -1.0 &&
                      (me.flags & kEdgeMaterialBoundary) != 0u)) return;
                flags |= EDGE_MATERIAL;
            }
            kind = EDGE_CREASE;  // a < b: the face that walks low -> high, as the geometry shader
        }
    }

    // A feature edge: to view space. Normals go with the cofactor matrix (right for any
    // invertible model-view), which maps the object-space cross product of a face's edges to
    // the view-space one.
#ifndef EDGE_WORK_LISTED
    ViewVertices v = view_vertices(inst, me, pa, has_b);
#endif
    mat4 mv = v.mv;
    mat3 l = mat3(mv);
    mat3 cof = mat3(cross(l[1], l[2]), cross(l[2], l[0]), cross(l[0], l[1]));
    vec3 a = v.a;
    vec3 b = v.b;
    vec3 na = cof * obj_na;
    vec3 nb = has_b ? cof * obj_nb : vec3(0.0);
    vec3 p0 = a, p1 = b, opp = v.opp_a;  // emitted direction and the emitting face's third vertex
    vec3 face_pos = plane_of(na, a), face_neg = vec3(0.0);
    if (kind == EDGE_SILHOUETTE) {
        // Emitted in the front face's winding with its third vertex.
        if (!front_a) { p0 = b; p1 = a; opp = v.opp_b; }
        face_pos = vec3(0.0);
    } else if (kind == EDGE_CREASE) {
        face_neg = plane_of(nb, v.opp_b);
    }

    vec3 m = eye_edge_plane(p0, p1, opp);
    ScreenEdge s;
    if (!project_edge(p0, p1, s)) return;

    uint slot = atomicAdd(vertex_count, EDGE_VERTICES) / EDGE_VERTICES;
    if (slot >= u_capacity) return;  // counted, so the renderer can grow the buffer
    bool reversed = kind == EDGE_SILHOUETTE && !front_a;
    // The record's face A is the emitting face: the front one of a silhouette.
    if (reversed) flags = (flags & ~EDGE_FACE_B_FRONT) | EDGE_FACE_A_FRONT;
    if (s.t.x > 0.0) flags |= EDGE_CLIPPED_START;
    if (s.t.y < 1.0) flags |= EDGE_CLIPPED_END;
    uint va = reversed ? me.b : me.a, vb = reversed ? me.a : me.b;
    // Room for the spine-visibility samples of the stretch on screen; an edge that finds no
    // room is tested per fragment (samples = 0).
    uint first_sample = 0u, samples = 0u;
    uvec2 sampled = uvec2(1u, 0u);
    if (u_sample_capacity > 0u) {
        uint n = spine_sample_count(s.s0, s.s1, u_sample_spacing);
        vec2 stretch = on_screen_stretch(s.s0, s.s1);
        uint want = 0u;
        if (stretch.x <= stretch.y) {
            sampled = uvec2(uint(floor(stretch.x * float(n - 1u))), min(uint(ceil(stretch.y * float(n - 1u))), n - 1u));
            want = sampled.y - sampled.x + 1u;
            first_sample = atomicAdd(samples_used, want);
        }
        if (want == 0u || (want <= u_sample_capacity && first_sample <= u_sample_capacity - want)) samples = n;
    }

    records[slot].screen = vec4(s.s0, s.s1);
    records[slot].depth = vec4(1.0 / s.w, s.t);
    records[slot].edge_plane = vec4(m, me.cos_dihedral);
    records[slot].face_pos = vec4(face_pos, 0.0);
    records[slot].face_neg = vec4(face_neg, 0.0);
#ifdef EDGE_RECORD_NORMALS
    // Only the strokes that shade by them read the normals (edge_buffer.h): every other frame
    // saves their loads, transforms and stores.
    records[slot].normal_a = vec4(unit_or_zero(reversed ? nb : na), 0.0);
    records[slot].normal_b = vec4(unit_or_zero(reversed ? na : nb), 0.0);
    records[slot].vertex_normal_a = vec4(unit_or_zero(cof * vertex_normal(va)), 0.0);
    records[slot].vertex_normal_b = vec4(unit_or_zero(cof * vertex_normal(vb)), 0.0);
#endif
    records[slot].ids = uvec4(kind | flags, inst, me.id, u_mesh_id);
    records[slot].vertices = uvec4(va, vb, first_sample, samples);
    if (samples > 0u) {  // none visible yet
        spans[2u * slot] = uvec4(sampled, 0xFFFFFFFFu, 0u);
        spans[2u * slot + 1u] = uvec4(0u);
    }
}

#ifdef EDGE_WORK_LISTED
// Listed work (render/lines/edge_prefilter.h): one edge per entry, x the instance, y the edge,
// z where its cluster's hierarchical-Z bounds record is (as an item index), w 1 on its
// cluster's first entry; one entry per invocation.
void main() {
    uint index = u_work_base + gl_GlobalInvocationID.x;
    if (index >= u_work_end) return;
    uvec4 entry = work[index];
    if (u_hiz && hidden_by_prepass(entry.z)) {
        if (entry.w != 0u) atomicAdd(hidden_items, 1u);
        return;
    }
    test_edge(entry.x, uintBitsToFloat(work[entry.x]), entry.y);
}
#else
// One work item (a cluster's edges, or its crease prefix) per group, each invocation taking
// every EDGE_GROUP_SIZE-th edge of it.
void main() {
    uint item_index = u_work_base + gl_WorkGroupID.x;
    if (u_hiz && hidden_by_prepass(item_index)) {
        if (gl_LocalInvocationID.x == 0u) atomicAdd(hidden_items, 1u);
        return;
    }
    uvec4 item = work[item_index];
    vec4 eye = uintBitsToFloat(work[item.x]);
    for (uint i = gl_LocalInvocationID.x; i < item.z; i += EDGE_GROUP_SIZE)
        test_edge(item.x, eye, item.y + i);
}
#endif
