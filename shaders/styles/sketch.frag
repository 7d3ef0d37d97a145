#version 450 core
// Pencil strokes (Olejnik & Litchmore, after Jezek et al. 2018). Each visible feature edge becomes
// u_strokes overlapping strokes; each stroke is split at a random point into two pieces whose
// end points are jittered. Every random number comes from the noise texture at texels picked
// by the edge's stable seed, never by the frame: a still camera draws the same picture, and a
// moving one moves the strokes with their edges instead of making them boil. Edges of little
// significance under the light are dropped; the rest get lighter or darker with it. With
// MASK_MODE it marks the pixels the strokes' centre lines cross, for scoring against the
// exact reference at a tolerance as wide as the jitter.
#include "../beam/beam.glsl"
#include "../lines/spine_test.glsl"
#include "stroke_varyings.glsl"

layout(binding = TEXTURE_UNIT_NOISE) uniform sampler2D u_noise;     // RGBA8 uniform noise, 256 x 256, repeat
uniform int u_strokes;
uniform float u_jitter_px;
uniform float u_width_px;
uniform float u_darkness;
uniform float u_min_significance;
uniform vec3 u_ink;

layout(location = 0) out vec4 o_color;

vec4 noise(uint n) {
    return texelFetch(u_noise, ivec2(int(n & 255u), int((n >> 8) & 255u)), 0);
}

float segment_distance(vec2 p, vec2 a, vec2 b) {
    return distance(p, mix(a, b, closest_t(p, a, b)));
}

#ifdef MASK_MODE
bool crosses_pixel(vec2 c, vec2 a, vec2 b) {
    vec2 lo = min(a, b), hi = max(a, b);
    if (hi.x < c.x - 0.5 || lo.x >= c.x + 0.5 || hi.y < c.y - 0.5 || lo.y >= c.y + 0.5) return false;
    vec2 d = b - a;
    vec2 n = vec2(-d.y, d.x);
    return abs(dot(n, c - a)) <= 0.5 * (abs(n.x) + abs(n.y));
}
#endif

void main() {
    if (g_significance < u_min_significance) discard;
#ifdef MASK_MODE
    vec2 p = gl_FragCoord.xy;
#else
    vec2 p = g_pixel;
#endif
    vec2 d = g_p1 - g_p0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float j = min(u_jitter_px, 0.25 * len + 0.5);
    float keep = 1.0;  // product of (1 - coverage): overlapping strokes darken
    bool hit = false;
    for (int s = 0; s < u_strokes; ++s) {
        uint n = g_seed + uint(s) * 0x9e37u;
        vec4 a = noise(n), b = noise(n ^ 0x5bd1u);
        float split = mix(0.3, 0.7, a.x);
        vec2 offset = nrm * (a.y - 0.5) * j;  // each stroke a little beside the others
        vec2 q0 = g_p0 + offset + (b.xy - 0.5) * 2.0 * j - dir * j * a.z;
        vec2 qm = mix(g_p0, g_p1, split) + offset;
        vec2 qm1 = qm + (b.zw - 0.5) * j;
        vec2 qm2 = qm - (b.wz - 0.5) * j;
        vec2 q1 = g_p1 + offset + (a.wz - 0.5) * 2.0 * j + dir * j * a.w;
#ifdef MASK_MODE
        hit = hit || crosses_pixel(p, q0, qm1) || crosses_pixel(p, qm2, q1);
#else
        float dist = min(segment_distance(p, q0, qm1), segment_distance(p, qm2, q1));
        float cover = clamp(u_width_px * 0.5 - dist + 0.5, 0.0, 1.0);
        keep *= 1.0 - cover * u_darkness * mix(0.55, 1.0, g_significance);
#endif
    }
#ifdef MASK_MODE
    if (!hit) discard;
#else
    if (keep >= 0.999) discard;
#endif
    // Visible where the edge itself is: the spine test at the nearest point of the true edge.
    float t = closest_t(p, g_p0, g_p1);
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, t);
    if (!spine_visible(mix(g_p0, g_p1, t), line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) discard;
#ifdef MASK_MODE
    o_color = vec4(1.0);
#else
    o_color = vec4(mix(vec3(1.0), u_ink, 1.0 - keep), 1.0);  // MIN blended onto the paper
#endif
}
