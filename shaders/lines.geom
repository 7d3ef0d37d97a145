#version 450 core
// Finds silhouette, crease and boundary edges of each triangle (GL_TRIANGLES_ADJACENCY:
// triangle 0-2-4, neighbour vertices 1, 3, 5) and extrudes each visible edge into a
// screen-space quad of constant pixel half-width, extended at both ends for round caps.
#include "beam_width.glsl"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;

in VertexData {
    vec3 view_pos;
    flat uint vertex_id;
    flat uint instance;
} v_in[];

// Cosine of the dihedral angle of each triangle edge, precomputed from object-space normals
// on the CPU (view-independent); 2.0 on edges without a usable neighbour.
layout(std430, binding = 0) readonly buffer EdgeCosines { float edge_cos[]; };

// The frame's per-instance data (render::InstanceData): 6 vec4 each, the model-view matrix in
// the first four, then colour (rgb * intensity), then parameters (x: cos(crease angle),
// z: intensity).
layout(std430, binding = 1) readonly buffer Instances { vec4 instance_data[]; };
vec4 instance_color(uint i) { return instance_data[i * 6u + 4u]; }
vec4 instance_params(uint i) { return instance_data[i * 6u + 5u]; }

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

const float kGuard = 2.0;  // lateral guard band: clip to twice the view frustum

vec3 face_normal(vec3 a, vec3 b, vec3 c) { return cross(b - a, c - a); }

bool front_facing(vec3 a, vec3 b, vec3 c) {
    // Camera at the view-space origin: robust for points behind the camera too.
    return dot(face_normal(a, b, c), -a) > 0.0;
}

// Clips segment a-b (view space) to near <= depth <= far. False if nothing is left.
bool clip_depth(inout vec3 a, inout vec3 b) {
    float da = -a.z, db = -b.z;
    if (da < u_near && db < u_near) return false;
    if (da > u_far && db > u_far) return false;
    if (da < u_near) a = mix(a, b, (u_near - da) / (db - da));
    else if (db < u_near) b = mix(b, a, (u_near - db) / (da - db));
    da = -a.z; db = -b.z;
    if (da > u_far) a = mix(a, b, (da - u_far) / (da - db));
    else if (db > u_far) b = mix(b, a, (db - u_far) / (db - da));
    return true;
}

// Clips a clip-space segment (w > 0 at both ends) to the guard band |x|,|y| <= kGuard * w.
bool clip_lateral(inout vec4 a, inout vec4 b) {
    for (int axis = 0; axis < 2; ++axis) {
        for (int side = -1; side <= 1; side += 2) {
            float fa = kGuard * a.w - float(side) * a[axis];
            float fb = kGuard * b.w - float(side) * b[axis];
            if (fa < 0.0 && fb < 0.0) return false;
            if (fa < 0.0) a = mix(a, b, fa / (fa - fb));
            else if (fb < 0.0) b = mix(b, a, fb / (fb - fa));
        }
    }
    return true;
}

vec2 to_window(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * u_viewport; }

// View-space ray (depth 1) through a window position.
vec3 ray_at(vec2 px) {
    vec2 ndc = px / u_viewport * 2.0 - 1.0;
    return vec3(ndc.x / u_proj[0][0], ndc.y / u_proj[1][1], -1.0);
}

// The plane through p with normal n, scaled so that dot(plane, X) = 1 on it. A plane through
// the eye (seen exactly edge-on) has no such form: zero, which means "use the spine's depth".
vec3 plane_of(vec3 n, vec3 p) {
    float k = dot(n, p);
    return abs(k) > 1e-30 ? n / k : vec3(0.0);
}

// kind: 0 = crease (faces on both sides), 1 = silhouette, 2 = boundary-like (one face).
// `face` is this triangle's plane, `other` the neighbour's (creases only); `opp` is this
// triangle's vertex off the edge, which tells on which side of the edge the face lies.
void emit_edge(int i0, int i1, int kind, vec3 face, vec3 other, vec3 opp) {
    vec3 a = v_in[i0].view_pos, b = v_in[i1].view_pos;
    // The plane through the eye and the (unclipped) edge, oriented so the face is positive.
    vec3 m = cross(a, b);
    if (dot(m, opp) < 0.0) m = -m;
    if (!clip_depth(a, b)) return;
    vec4 ca = u_proj * vec4(a, 1.0), cb = u_proj * vec4(b, 1.0);
    if (!clip_lateral(ca, cb)) return;
    vec2 s0 = to_window(ca), s1 = to_window(cb);
    vec2 d = s1 - s0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    uint instance = v_in[0].instance;
    BeamShape beam = beam_shape(instance_params(instance).z, len,
                                (instance * 0x01000193u) ^ uint(gl_PrimitiveIDIn * 3 + i0 / 2));
    float h = beam.half_width;

    g_edge_plane = m;
    g_face_pos = kind == 1 ? vec3(0.0) : face;
    g_face_neg = kind == 0 ? other : vec3(0.0);
    g_nudge = vec2(0.0);
    if (kind == 1) {
        // Sample the depth just outside the front face, where the background or an occluder is.
        g_nudge = (dot(m, ray_at(s0 + nrm)) > 0.0 ? -nrm : nrm) * 0.75;
    }
    g_p0 = s0;
    g_p1 = s1;
    g_inv_depth = vec2(1.0 / ca.w, 1.0 / cb.w);
    g_color = instance_color(instance).rgb;
    g_beam = vec3(beam.half_width, beam.gain, beam.softness);
    vec2 corners[4] = vec2[4](s0 - dir * h - nrm * h, s0 - dir * h + nrm * h,
                              s1 + dir * h - nrm * h, s1 + dir * h + nrm * h);
    for (int k = 0; k < 4; ++k) {
        g_pixel = corners[k];
        gl_Position = vec4(corners[k] / u_viewport * 2.0 - 1.0, 0.0, 1.0);
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
                       edge_cos[base + e] < cos_crease) {
                kind = 0;  // crease, emitted once: by the face that sees the edge low -> high
                other = plane_of(n_nb, q);
            }
        }
        if (kind >= 0) emit_edge(i0, i1, kind, face, other, v_in[iopp].view_pos);
    }
}
