#version 450 core
// Haloed outline strokes (Loviscach, after McGuire & Hughes 2004). The quads are depth-tested
// in hardware against the shrunk-mesh depth mask, so a stroke reaches both inside and outside
// its silhouette and is still hidden by whatever is in front of it.
//   default:   the ink: u_strokes strokes in one pass, each its own row of the 1D profile
//              texture and its own offset, read from the offset texture at the fragment's
//              image position; creases get one thin stroke
//   HALO_GLOW: the soft halo outside each silhouette into the off-screen halo buffer, MAX
//              blended: r = strength, g = the stroke's inverse depth (what it may cover)
// Cubic smoothing bends each silhouette's chord into the Hermite curve whose tangents run
// perpendicular to the projected vertex normals at both ends (g_slopes), so a coarse mesh
// outlines as a smooth curve.
#include "../beam/beam.glsl"
#include "stroke_varyings.glsl"

layout(binding = TEXTURE_UNIT_PROFILE) uniform sampler2D u_profile;   // RG: ink across the stroke (0 inner .. 1 outer), halo beyond
layout(binding = TEXTURE_UNIT_OFFSET) uniform sampler2D u_offset;    // RG: smooth offsets in pixels, repeat
uniform int u_strokes;
uniform float u_inner_px;
uniform float u_outer_px;
uniform float u_halo_px;
uniform vec3 u_ink;
layout(binding = TEXTURE_UNIT_HALO) uniform sampler2D u_halo;      // strokes: the halo buffer, so nearer halos cover farther ink

layout(location = 0) out vec4 o_color;

// Signed distance from the (smoothed) silhouette curve, positive outward, and the position
// along the chord (0..1).
vec2 curve_frame(vec2 p) {
    vec2 d = g_p1 - g_p0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float s = clamp(dot(p - g_p0, dir) / max(len, 1e-6), 0.0, 1.0);
    // Hermite with zero offset at both ends and slopes m0, m1: f = L (m0 h10 + m1 h11).
    float h10 = s * s * s - 2.0 * s * s + s, h11 = s * s * s - s * s;
    float dh10 = 3.0 * s * s - 4.0 * s + 1.0, dh11 = 3.0 * s * s - 2.0 * s;
    float f = len * (g_slopes.x * h10 + g_slopes.y * h11);
    float slope = g_slopes.x * dh10 + g_slopes.y * dh11;
    vec2 on_chord = g_p0 + dir * s * len;
    float across = dot(p - on_chord, nrm) - f;
    // Beyond the ends the distance is to the end point.
    vec2 end_gap = p - (s <= 0.0 ? g_p0 : g_p1);
    float beyond = (s <= 0.0 || s >= 1.0) ? length(end_gap - nrm * dot(end_gap, nrm)) : 0.0;
    float side = g_kind == KIND_SILHOUETTE ? sign(dot(g_outward, nrm)) : 1.0;
    float dist = across / sqrt(1.0 + slope * slope);
    return vec2(dist * side, beyond);
}

void main() {
    vec2 frame = curve_frame(g_pixel);
    float out_d = frame.x;   // + outward
    float beyond = frame.y;  // past an end
    float end_fade = clamp(1.0 - beyond / max(u_inner_px, 0.5), 0.0, 1.0);
#ifdef HALO_GLOW
    if (g_kind != KIND_SILHOUETTE || out_d < 0.0) discard;
    float x = out_d / (u_outer_px + u_halo_px);
    if (x >= 1.0) discard;
    float strength = texture(u_profile, vec2(x, 0.5 / 4.0)).g * end_fade;
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, clamp(dot(g_pixel - g_p0, g_p1 - g_p0) /
                                                              max(dot(g_p1 - g_p0, g_p1 - g_p0), 1e-12), 0.0, 1.0));
    o_color = vec4(strength, line_inv, 0.0, 1.0);
#else
    float ink = 0.0;
    // The offsets move a stroke by at most kMaxOffsetPx (style_textures.cpp: offsets within
    // [-1, 1], times 1.2): past that no stroke reaches the fragment, and its texture taps are
    // skipped (a fifth of the quad's fragments, which stroke.vert sizes with a margin).
    const float kMaxOffsetPx = 1.2;
    bool in_reach = out_d >= -u_inner_px - kMaxOffsetPx && out_d <= u_outer_px + kMaxOffsetPx;
    if (g_kind == KIND_SILHOUETTE || g_kind == 2u) {
        for (int k = 0; k < u_strokes && in_reach; ++k) {
            vec2 o = texture(u_offset, g_pixel / 97.0 + vec2(0.37, 0.61) * float(k)).rg;
            float x = (out_d + o.x * kMaxOffsetPx + u_inner_px) / (u_inner_px + u_outer_px);
            if (x < 0.0 || x > 1.0) continue;
            float row = (float(k % 4) + 0.5) / 4.0;
            ink = max(ink, texture(u_profile, vec2(x, row)).r * mix(0.6, 1.0, o.y * 0.5 + 0.5));
        }
    } else {
        ink = clamp(1.0 - abs(out_d) + 0.25, 0.0, 1.0) * 0.8;  // creases: one thin line
    }
    ink *= end_fade;
    // A nearer silhouette's halo covers this stroke like it covers the fill behind it, but
    // only where the stroke lies well behind it (the caster at least kHaloDepthGap nearer in
    // inverse depth): a line behind another object breaks off before it (Loviscach), while the
    // lines of the same part near its own silhouettes (the far edge of a thin leg, a crease
    // beside a wheel's outline) are visible features and stay. With the paper's 2% gap the
    // halo erased up to a quarter of the visible lines of thin and vehicle models.
    const float kHaloDepthGap = 1.25;
    vec2 halo = texelFetch(u_halo, ivec2(floor(g_pixel)), 0).rg;
    float t = closest_t(g_pixel, g_p0, g_p1);
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, t);
    if (halo.g > line_inv * kHaloDepthGap) ink *= 1.0 - clamp(halo.r, 0.0, 1.0);
    if (ink <= 0.01) discard;
    o_color = vec4(mix(vec3(1.0), u_ink, ink), 1.0);  // MIN blended
#endif
}
