// Edge geometry shared by both line methods (lines.geom and edges.comp + edge_quad.vert), so
// they classify, clip and extrude with the same arithmetic. Needs these uniforms declared
// before the include: u_proj, u_viewport, u_near, u_far.

const float kGuard = 2.0;  // lateral guard band: clip to twice the view frustum

vec3 face_normal(vec3 a, vec3 b, vec3 c) { return cross(b - a, c - a); }

// Camera at the view-space origin: robust for points behind the camera too.
bool faces_eye(vec3 n, vec3 p) { return dot(n, -p) > 0.0; }

// Clips segment a-b (view space) to near <= depth <= far. False if nothing is left. t holds
// the parameters of a and b on the unclipped segment and follows the clip.
bool clip_depth(inout vec3 a, inout vec3 b, inout vec2 t) {
    float da = -a.z, db = -b.z;
    if (da < u_near && db < u_near) return false;
    if (da > u_far && db > u_far) return false;
    if (da < u_near) { float k = (u_near - da) / (db - da); a = mix(a, b, k); t.x = mix(t.x, t.y, k); }
    else if (db < u_near) { float k = (u_near - db) / (da - db); b = mix(b, a, k); t.y = mix(t.y, t.x, k); }
    da = -a.z; db = -b.z;
    if (da > u_far) { float k = (da - u_far) / (da - db); a = mix(a, b, k); t.x = mix(t.x, t.y, k); }
    else if (db > u_far) { float k = (db - u_far) / (db - da); b = mix(b, a, k); t.y = mix(t.y, t.x, k); }
    return true;
}

// Clips a clip-space segment (w > 0 at both ends) to the guard band |x|,|y| <= kGuard * w.
bool clip_lateral(inout vec4 a, inout vec4 b, inout vec2 t) {
    for (int axis = 0; axis < 2; ++axis) {
        for (int side = -1; side <= 1; side += 2) {
            float fa = kGuard * a.w - float(side) * a[axis];
            float fb = kGuard * b.w - float(side) * b[axis];
            if (fa < 0.0 && fb < 0.0) return false;
            if (fa < 0.0) { float k = fa / (fa - fb); a = mix(a, b, k); t.x = mix(t.x, t.y, k); }
            else if (fb < 0.0) { float k = fb / (fb - fa); b = mix(b, a, k); t.y = mix(t.y, t.x, k); }
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

// The plane through the eye and the edge a-b, oriented so that `opp` (the face's third vertex)
// is on its positive side.
vec3 eye_edge_plane(vec3 a, vec3 b, vec3 opp) {
    vec3 m = cross(a, b);
    return dot(m, opp) < 0.0 ? -m : m;
}

// A clipped, projected edge: its window end points and clip-space w (view depth) at each end.
struct ScreenEdge {
    vec2 s0, s1;
    vec2 w;   // clip w at s0, s1
    vec2 t;   // parameters of s0, s1 on the unclipped edge
};

// Near/far clipping in view space, then the guard band. False when nothing is left.
bool project_edge(vec3 a, vec3 b, out ScreenEdge e) {
    e.t = vec2(0.0, 1.0);
    if (!clip_depth(a, b, e.t)) return false;
    vec4 ca = u_proj * vec4(a, 1.0), cb = u_proj * vec4(b, 1.0);
    if (!clip_lateral(ca, cb, e.t)) return false;
    e.s0 = to_window(ca);
    e.s1 = to_window(cb);
    e.w = vec2(ca.w, cb.w);
    return true;
}

// Unit direction and normal of the spine s0 -> s1 (x axis for a point).
void spine_frame(vec2 s0, vec2 s1, out vec2 dir, out vec2 nrm) {
    vec2 d = s1 - s0;
    float len = length(d);
    dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    nrm = vec2(-dir.y, dir.x);
}

// Corner k (0..3, triangle-strip order) of the quad around the spine: h to each side, and
// `reach` past both ends (h for round caps, more for lengthened ends: beam_ends.glsl).
vec2 quad_corner(vec2 s0, vec2 s1, vec2 dir, vec2 nrm, float h, float reach, int k) {
    vec2 end = (k < 2) ? s0 - dir * reach : s1 + dir * reach;
    return end + ((k & 1) == 0 ? -nrm : nrm) * h;
}

// Pixel offset that moves a silhouette's depth sample just outside its front face, where the
// background or an occluder is.
vec2 silhouette_nudge(vec3 edge_plane, vec2 s0, vec2 nrm) {
    return (dot(edge_plane, ray_at(s0 + nrm)) > 0.0 ? -nrm : nrm) * 0.75;
}
