#version 450 core
// LineMethod::compute: draws one quad (two triangles, EDGE_VERTICES vertices) per record of the
// edge buffer that shaders/edges.comp filled, with no geometry shader. It hands lines.frag the
// same varyings as lines.geom, computed with the same code (edge_geometry.glsl), so the
// fragment stage - spine test and beam - is shared by both line methods.
#include "edge_record.glsl"
#include "beam_width.glsl"
#include "spine_samples.glsl"

layout(std430, binding = EDGE_RECORDS_BINDING) readonly buffer Records { EdgeRecord records[]; };
layout(std430, binding = 1) readonly buffer Instances { vec4 instance_data[]; };
layout(std430, binding = SPINE_SPANS_BINDING) readonly buffer Spans { uvec4 spans[]; };

uniform uint u_capacity;  // records the buffer holds (the draw count may run past it)
uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;

noperspective out vec2 g_pixel;
flat out vec2 g_p0;
flat out vec2 g_p1;
flat out vec2 g_inv_depth;
flat out vec3 g_edge_plane;
flat out vec3 g_face_pos;
flat out vec3 g_face_neg;
flat out vec2 g_nudge;
flat out vec3 g_color;
flat out vec3 g_beam;  // half-width (px), gain, softness (beam_width.glsl)
flat out uvec4 g_samples;  // first stored sample, sample count (0: test here), sampled stretch
flat out vec2 g_visible_t; // the visible stretch of the spine (t), with g_samples
flat out uint g_lookup;    // 1: the stretch has hidden samples inside, look each one up

#include "edge_geometry.glsl"

// Two triangles of the strip-ordered corners 0 1 2 3.
const int kCorner[6] = int[6](0, 1, 2, 2, 1, 3);

void main() {
    uint index = uint(gl_VertexID) / EDGE_VERTICES;
    if (index >= u_capacity) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: drawn by nobody
        return;
    }
    EdgeRecord r = records[index];
    vec2 s0 = r.screen.xy, s1 = r.screen.zw;
    vec2 dir, nrm;
    spine_frame(s0, s1, dir, nrm);
    uint kind = r.ids.x & EDGE_KIND_MASK;
    g_p0 = s0;
    g_p1 = s1;
    g_inv_depth = r.depth.xy;
    g_edge_plane = r.edge_plane.xyz;
    g_face_pos = r.face_pos.xyz;
    g_face_neg = r.face_neg.xyz;
    g_nudge = kind == EDGE_SILHOUETTE ? silhouette_nudge(r.edge_plane.xyz, s0, nrm) : vec2(0.0);
    uint instance = r.ids.y;
    g_color = instance_data[instance * 6u + 4u].rgb;
    // The beam's shape per edge; the flicker key is the edge's own id in its mesh and instance.
    BeamShape beam = beam_shape(instance_data[instance * 6u + 5u].z, length(s1 - s0),
                                (instance * 0x01000193u) ^ r.ids.z);
    g_beam = vec3(beam.half_width, beam.gain, beam.softness);
    g_samples = uvec4(r.vertices.zw, 0u, 0u);
    g_visible_t = vec2(-1.0, 2.0);
    g_lookup = 0u;
    // With spine samples the quad covers only the visible stretch: from half a sample before
    // the first visible sample to half a sample after the last, where the look-up would turn
    // hidden. A wholly hidden edge draws nothing; a stretch without hidden samples inside
    // needs no look-ups, only the stretch's ends (lines.frag).
    vec2 q0 = s0, q1 = s1;
    if (g_samples.y > 0u) {
        uvec4 span = spans[2u * index];
        uint visible_n = spans[2u * index + 1u].x;
        g_samples.zw = span.xy;
        if (span.z > span.w) {
            gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
            return;
        }
        g_lookup = visible_n < span.w - span.z + 1u ? 1u : 0u;
        if (g_samples.y > 1u) {
            float steps = float(g_samples.y - 1u);
            g_visible_t = vec2((float(span.z) - 0.5) / steps, (float(span.w) + 0.5) / steps);
            q0 = mix(s0, s1, max(g_visible_t.x, 0.0));
            q1 = mix(s0, s1, min(g_visible_t.y, 1.0));
        }
    }
    g_pixel = quad_corner(q0, q1, dir, nrm, beam.half_width, kCorner[uint(gl_VertexID) % EDGE_VERTICES]);
    gl_Position = vec4(g_pixel / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
