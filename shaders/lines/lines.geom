#version 450 core
// Finds silhouette, crease and boundary edges (and material boundaries, when asked) of each
// triangle (GL_TRIANGLES_ADJACENCY:
// triangle 0-2-4, neighbour vertices 1, 3, 5) and extrudes each visible edge into a
// screen-space quad of constant pixel half-width, extended at both ends for round caps.
#include "../beam/beam_width.glsl"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;

in VertexData {
    vec3 view_pos;
    flat uint vertex_id;
    flat uint instance;
} v_in[];

// Cosine of the dihedral angle of each triangle edge, precomputed from object-space normals
// on the CPU (view-independent); 2.0 on edges without a usable neighbour.
layout(std430, binding = EDGE_COSINES_BINDING) readonly buffer EdgeCosines { float edge_cos[]; };
// Per triangle, bit e set where edge e is a material boundary (geo::AdjacencyMesh::
// material_edges, view-independent like the cosines). Read only when u_material_lines is set,
// which the renderer sets only for a mesh that has material boundaries.
layout(std430, binding = EDGE_MATERIALS_BINDING) readonly buffer EdgeMaterials { uint edge_materials[]; };
uniform bool u_material_lines;

// The frame's per-instance data (render::InstanceData): colour (rgb * intensity) and
// parameters (x: cos(crease angle), z: intensity).
#include "../instance_data.glsl"

// Set for an outward-closed mesh seen from outside: its back faces are hidden by its front
// faces, so a back-facing triangle has nothing visible to emit (its silhouettes are emitted by
// the front-facing neighbours).
uniform bool u_skip_back_faces;
uniform int u_edges_to_test;  // always 3; a uniform bound stops the compiler unrolling the loop

uniform mat4 u_proj;
uniform vec2 u_viewport;       // pixels
uniform float u_near;
uniform float u_far;

noperspective out vec2 g_pixel;  // this corner's window position, interpolated linearly
flat out vec2 g_p0;              // spine end points, window pixels
flat out vec2 g_p1;
flat out vec2 g_inv_depth;       // 1 / view depth at p0 and p1 (linear in screen space)
flat out vec3 g_edge_plane;      // view-space plane through the eye and the edge
flat out vec3 g_face_pos;        // plane of the face on the edge plane's positive side, as
                                 // n / (n.p) so that 1/depth along a ray r is dot(plane, r)
flat out vec3 g_face_neg;        // ... negative side; all zero: compare with the spine's depth
flat out vec2 g_nudge;           // pixel offset that moves a silhouette sample off its own face
flat out vec3 g_color;
flat out vec3 g_beam;            // half-width (px), gain, softness (beam_width.glsl)

#include "edge_geometry.glsl"
#include "../beam/beam_tiles.glsl"

// kind: 0 = crease (faces on both sides), 1 = silhouette, 2 = boundary-like (one face).
// `face` is this triangle's plane, `other` the neighbour's (creases only); `opp` is this
// triangle's vertex off the edge, which tells on which side of the edge the face lies.
void emit_edge(int i0, int i1, int kind, vec3 face, vec3 other, vec3 opp) {
    vec3 a = v_in[i0].view_pos, b = v_in[i1].view_pos;
    // The plane through the eye and the (unclipped) edge, oriented so the face is positive.
    vec3 m = eye_edge_plane(a, b, opp);
    ScreenEdge e;
    if (!project_edge(a, b, e)) return;
    vec2 dir, nrm;
    spine_frame(e.s0, e.s1, dir, nrm);
    uint instance = v_in[0].instance;
    BeamShape beam = beam_shape(instance_params(instance).z, length(e.s1 - e.s0),
                                (instance * 0x01000193u) ^ uint(gl_PrimitiveIDIn * 3 + i0 / 2));

    g_edge_plane = m;
    g_face_pos = kind == 1 ? vec3(0.0) : face;
    g_face_neg = kind == 0 ? other : vec3(0.0);
    g_nudge = kind == 1 ? silhouette_nudge(m, e.s0, nrm) : vec2(0.0);
    g_p0 = e.s0;
    g_p1 = e.s1;
    g_inv_depth = 1.0 / e.w;
    g_color = instance_color(instance).rgb;
    g_beam = vec3(beam.half_width, beam.gain, beam.softness);
    mark_beam_segment(e.s0, e.s1, beam.half_width, beam_end_reach(beam.half_width));
    for (int k = 0; k < 4; ++k) {
        g_pixel = quad_corner(e.s0, e.s1, dir, nrm, beam.half_width, beam_end_reach(beam.half_width), k);
        gl_Position = vec4(g_pixel / u_viewport * 2.0 - 1.0, 0.0, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}

void main() {
    vec3 p0 = v_in[0].view_pos, p2 = v_in[2].view_pos, p4 = v_in[4].view_pos;
    vec3 n_view = face_normal(p0, p2, p4);
    bool front = dot(n_view, -p0) > 0.0;
    if (!front && u_skip_back_faces) return;
    vec3 face = plane_of(n_view, p0);
    float cos_crease = instance_params(v_in[0].instance).x;
    int base = gl_PrimitiveIDIn * 3;
    // Material boundaries follow the creases' distance LOD: an object too small for any crease
    // (cos_crease below -1) draws none.
    uint material_bits = u_material_lines && cos_crease >= -1.0 ? edge_materials[gl_PrimitiveIDIn] : 0u;

    for (int e = 0; e < u_edges_to_test; ++e) {
        int i0 = 2 * e, iadj = 2 * e + 1, i1 = (2 * e + 2) % 6, iopp = (2 * e + 4) % 6;
        int kind = -1;  // 0 crease, 1 silhouette, 2 boundary-like
        vec3 other = vec3(0.0);
        if (v_in[iadj].vertex_id == v_in[i0].vertex_id) {
            kind = 2;  // boundary, non-manifold or inconsistently wound: always a feature edge
        } else {
            vec3 a = v_in[i0].view_pos, q = v_in[iadj].view_pos, b = v_in[i1].view_pos;
            vec3 n_nb = face_normal(a, q, b);
            bool neighbour_front = dot(n_nb, -a) > 0.0;
            if (front && !neighbour_front) {
                kind = 1;  // silhouette, emitted by the front face
            } else if (front == neighbour_front && v_in[i0].vertex_id < v_in[i1].vertex_id &&
                       (edge_cos[base + e] < cos_crease || (material_bits & (1u << e)) != 0u)) {
                // crease or material boundary, emitted once: by the face that sees the edge
                // low -> high
                kind = 0;
                other = plane_of(n_nb, q);
            }
        }
        if (kind >= 0) emit_edge(i0, i1, kind, face, other, v_in[iopp].view_pos);
    }
}
