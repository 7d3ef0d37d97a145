#version 450 core
// Intersection lines (RenderSettings::intersection_lines): one invocation per segment where
// two occluders' surfaces cross, found on the CPU (render/gpu_scene/intersection_cache.h) and
// handed over in view space with the unit normals of the two faces it lies on. Each visible
// one is appended to the edge buffer as a crease flagged EDGE_INTERSECTION, so the spine test
// against the prepass, the quads and the styles treat it as they treat a crease; clipping
// and the spine samples are edges.comp's.
//
// The spine test's faces: the segment lies on both planes, so they meet on the eye-edge plane
// and on each side of it the nearer one is what the prepass holds there (both faces run on
// across the segment). Their difference is a multiple of the eye-edge plane, whose sign says
// which is nearer on the positive side.
#include "edge_record.glsl"
#include "spine_samples.glsl"

layout(local_size_x = 64) in;

struct Intersection {
    vec4 a;         // xyz: end a, view space
    vec4 b;         // xyz: end b
    vec4 normal_a;  // xyz: unit view-space normal of the first face
    vec4 normal_b;  // xyz: ... of the second
    uvec4 ids;      // x: instance (colour, beam), y: stable id, z: mesh id, w: 0
};
layout(std430, binding = INTERSECTIONS_BINDING) readonly buffer Intersections { Intersection segments[]; };
layout(std430, binding = EDGE_RECORDS_BINDING) writeonly buffer Records { EdgeRecord records[]; };
layout(std430, binding = SPINE_SPANS_BINDING) writeonly buffer Spans { uvec4 spans[]; };
layout(std430, binding = EDGE_COMMAND_BINDING) buffer Command { EDGE_COMMAND_MEMBERS; };

uniform uint u_count;           // segments in the buffer
uniform uint u_capacity;        // records the edge buffer holds
uniform uint u_sample_capacity; // spine samples it holds (0: none wanted)
uniform float u_sample_margin;
uniform float u_sample_spacing;
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;

#include "edge_geometry.glsl"

// Welded vertex ids for chaining: above any mesh's, two per segment, so that no stroke chains
// an intersection to a mesh edge.
const uint kFirstFreeVertex = 0x80000000u;

// As edges.comp's: the stretch (t0, t1) of the spine within the viewport grown by the margin.
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

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_count) return;
    Intersection x = segments[i];
    vec3 a = x.a.xyz, b = x.b.xyz;
    vec3 m = cross(a, b);
    vec3 plane_a = plane_of(x.normal_a.xyz, a), plane_b = plane_of(x.normal_b.xyz, a);
    bool a_nearer_on_pos = dot(plane_a - plane_b, m) > 0.0;
    ScreenEdge s;
    if (!project_edge(a, b, s)) return;

    uint slot = atomicAdd(vertex_count, EDGE_VERTICES) / EDGE_VERTICES;
    if (slot >= u_capacity) return;  // counted, so the renderer can grow the buffer
    uint flags = EDGE_INTERSECTION | EDGE_HAS_FACE_B;
    if (faces_eye(x.normal_a.xyz, a)) flags |= EDGE_FACE_A_FRONT;
    if (faces_eye(x.normal_b.xyz, a)) flags |= EDGE_FACE_B_FRONT;
    if (s.t.x > 0.0) flags |= EDGE_CLIPPED_START;
    if (s.t.y < 1.0) flags |= EDGE_CLIPPED_END;
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

    EdgeRecord r;
    r.screen = vec4(s.s0, s.s1);
    r.depth = vec4(1.0 / s.w, s.t);
    r.edge_plane = vec4(m, dot(x.normal_a.xyz, x.normal_b.xyz));
    r.face_pos = vec4(a_nearer_on_pos ? plane_a : plane_b, 0.0);
    r.face_neg = vec4(a_nearer_on_pos ? plane_b : plane_a, 0.0);
    r.normal_a = vec4(x.normal_a.xyz, 0.0);
    r.normal_b = vec4(x.normal_b.xyz, 0.0);
    // No smooth normal along a crossing: the faces' mean.
    vec3 mean = x.normal_a.xyz + x.normal_b.xyz;
    vec3 vn = length(mean) > 1e-6 ? normalize(mean) : x.normal_a.xyz;
    r.vertex_normal_a = vec4(vn, 0.0);
    r.vertex_normal_b = vec4(vn, 0.0);
    r.ids = uvec4(EDGE_CREASE | flags, x.ids.x, x.ids.y, x.ids.z);
    r.vertices = uvec4(kFirstFreeVertex + 2u * i, kFirstFreeVertex + 2u * i + 1u, first_sample, samples);
    records[slot] = r;
    if (samples > 0u) {  // none visible yet
        spans[2u * slot] = uvec4(sampled, 0xFFFFFFFFu, 0u);
        spans[2u * slot + 1u] = uvec4(0u);
    }
}
