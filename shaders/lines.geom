#version 450 core
// Finds silhouette, crease and boundary edges of each triangle (GL_TRIANGLES_ADJACENCY:
// triangle 0-2-4, neighbour vertices 1, 3, 5) and extrudes each visible edge into a
// screen-space quad of constant pixel half-width, extended at both ends for round caps.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;

in VertexData {
    vec3 view_pos;
    vec3 object_pos;
    flat uint vertex_id;
    flat vec4 color;
    flat float cos_crease;
} v_in[];

uniform mat4 u_proj;
uniform vec2 u_viewport;       // pixels
uniform float u_half_width;    // pixels
uniform float u_near;
uniform float u_far;
uniform float u_depth_bias;    // relative
uniform float u_slope_pixels;  // how many pixels of face slope the spine test tolerates

noperspective out vec2 g_pixel;  // this corner's window position, interpolated linearly
flat out vec2 g_p0;              // spine end points, window pixels
flat out vec2 g_p1;
flat out vec2 g_inv_depth;       // 1 / view depth at p0 and p1 (linear in screen space)
flat out float g_slack;          // depth tolerance of the spine test, view units per unit depth
flat out vec2 g_nudge;           // pixel offset that moves a silhouette sample off its own face
flat out vec3 g_color;

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

// Depth change per pixel of the plane through `p` with normal `n` (view space), at p.
float depth_slope(vec3 n, vec3 p) {
    float len = length(n);
    if (len < 1e-30) return 0.0;
    n /= len;
    float k = dot(n, p);
    float v = -p.z;
    float gx = n.x / u_proj[0][0] * 2.0 / u_viewport.x;
    float gy = n.y / u_proj[1][1] * 2.0 / u_viewport.y;
    return v * v / max(abs(k), 1e-20) * length(vec2(gx, gy));
}

void emit_edge(int i0, int i1, vec3 slope_normal, bool nudge_away, int i_opposite) {
    vec3 a = v_in[i0].view_pos, b = v_in[i1].view_pos;
    if (!clip_depth(a, b)) return;
    vec4 ca = u_proj * vec4(a, 1.0), cb = u_proj * vec4(b, 1.0);
    if (!clip_lateral(ca, cb)) return;
    // Depth after lateral clipping, from w (= view depth for a perspective projection).
    vec2 s0 = to_window(ca), s1 = to_window(cb);
    vec2 d = s1 - s0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float h = u_half_width;

    vec3 mid = 0.5 * (a + b);
    float slack = u_depth_bias + u_slope_pixels * depth_slope(slope_normal, mid) / max(-mid.z, 1e-20);
    g_slack = min(slack, 0.25);
    g_nudge = vec2(0.0);
    if (nudge_away) {
        // Sample the depth just outside the front face, where the background or an occluder is.
        vec4 co = u_proj * vec4(v_in[i_opposite].view_pos, 1.0);
        vec2 so = co.w > 0.0 ? to_window(co) : s0 - nrm;
        g_nudge = (dot(so - s0, nrm) > 0.0 ? -nrm : nrm) * 0.75;
    }
    g_p0 = s0;
    g_p1 = s1;
    g_inv_depth = vec2(1.0 / ca.w, 1.0 / cb.w);
    g_color = v_in[0].color.rgb;
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
    vec3 n_obj = face_normal(v_in[0].object_pos, v_in[2].object_pos, v_in[4].object_pos);
    float n_obj_len = length(n_obj);
    n_obj = n_obj_len > 1e-30 ? n_obj / n_obj_len : vec3(0.0);
    float cos_crease = v_in[0].cos_crease;

    for (int e = 0; e < 3; ++e) {
        int i0 = 2 * e, iadj = 2 * e + 1, i1 = (2 * e + 2) % 6, iopp = (2 * e + 4) % 6;
        if (v_in[iadj].vertex_id == v_in[i0].vertex_id) {
            // Boundary, non-manifold or inconsistently wound: always a feature edge.
            emit_edge(i0, i1, n_view, false, iopp);
            continue;
        }
        vec3 q = v_in[iadj].view_pos;
        bool neighbour_front = front_facing(v_in[i0].view_pos, q, v_in[i1].view_pos);
        if (front && !neighbour_front) {
            emit_edge(i0, i1, n_view, true, iopp);  // silhouette, emitted by the front face
            continue;
        }
        if (front != neighbour_front) continue;  // silhouette owned by the other face
        if (v_in[i0].vertex_id > v_in[i1].vertex_id) continue;  // each crease once
        vec3 m_obj = face_normal(v_in[i0].object_pos, v_in[iadj].object_pos, v_in[i1].object_pos);
        float m_len = length(m_obj);
        if (m_len < 1e-30 || n_obj_len < 1e-30) continue;
        if (dot(n_obj, m_obj / m_len) < cos_crease) {
            vec3 n_nb = face_normal(v_in[i0].view_pos, q, v_in[i1].view_pos);
            // Tolerate the steeper of the two faces the spine pixel may land on.
            vec3 mid = 0.5 * (v_in[i0].view_pos + v_in[i1].view_pos);
            vec3 steeper = depth_slope(n_view, mid) > depth_slope(n_nb, mid) ? n_view : n_nb;
            emit_edge(i0, i1, steeper, false, iopp);
        }
    }
}
