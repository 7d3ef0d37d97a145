#version 450 core
// LineMethod::compute: draws one quad (two triangles, EDGE_VERTICES vertices) per record of the
// edge buffer that shaders/edges.comp filled, with no geometry shader. It hands lines.frag the
// same varyings as lines.geom, computed with the same code (edge_geometry.glsl), so the
// fragment stage - spine test and beam - is shared by both line methods.
#include "edge_record.glsl"
#include "beam_width.glsl"

layout(std430, binding = EDGE_RECORDS_BINDING) readonly buffer Records { EdgeRecord records[]; };
layout(std430, binding = 1) readonly buffer Instances { vec4 instance_data[]; };

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
    g_pixel = quad_corner(s0, s1, dir, nrm, beam.half_width, beam_end_reach(beam.half_width),
                          kCorner[uint(gl_VertexID) % EDGE_VERTICES]);
    gl_Position = vec4(g_pixel / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
