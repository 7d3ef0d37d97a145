#version 450 core
// Toon and pop-art outlines (Castro & Macedo): solid ink over the fill. Centred quads keep a
// fragment when the spine test passes at its nearest spine point; one-sided silhouette quads
// lie outside the object and are tested against the depth at the fragment itself (Castro &
// Macedo's "extruded outward, depth-tested"). Edges are antialiased over one pixel.
// With u_hidden_levels > 0 (technical) a centred quad whose spine point is hidden is drawn
// too, up to that occlusion level (occlusion_level.glsl): thinner, paler with each level, and
// dashed from the record's first end. With MASK_MODE it marks instead each pixel the spine
// crosses, 255 - 64 x the level (RenderSettings::mask_occlusion_levels).
#include "../beam/beam.glsl"
#include "../lines/spine_test.glsl"
#include "../lines/occlusion_level.glsl"
#include "stroke_varyings.glsl"
#ifdef MASK_MODE
#include "../lines/pixel_cross.glsl"
#endif

uniform float u_width_px;
uniform float u_overdraw;
uniform bool u_one_sided;
uniform vec3 u_ink;
uniform int u_hidden_levels;        // 0: visible lines only
uniform float u_hidden_width_scale;
uniform float u_dash_px;
uniform float u_gap_px;

layout(location = 0) out vec4 o_color;

// A visible stroke: the outline of toon and pop-art, technical's solid lines. `tested`: the
// caller found the spine point visible already.
void visible_stroke(bool tested) {
    vec2 p = g_pixel;
    vec2 d = g_p1 - g_p0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    // Along the edge: the spine runs past both ends by the overdraw.
    float along = dot(p - g_p0, dir);
    float ext = u_overdraw * len;
    float t = closest_t(p, g_p0, g_p1);
    vec2 spine = mix(g_p0, g_p1, t);
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, t);
    vec2 nrm = vec2(-dir.y, dir.x);
    float across = dot(p - g_p0, nrm);
    float outside_ends = max(-ext - along, along - len - ext);
    float cover;
    if (u_one_sided && g_kind == KIND_SILHOUETTE) {
        float out_d = across * sign(dot(g_outward, nrm));  // 0 at the spine, + outward
        cover = clamp(out_d + 0.5, 0.0, 1.0) * clamp(u_width_px - out_d + 0.5, 0.0, 1.0);
        // Depth-tested where it lands: an object in front of the silhouette hides it.
        ivec2 px = ivec2(floor(p));
        if (u_occlusion && !sample_visible(px, p, line_inv, EdgeFaces(vec3(0.0), vec3(0.0), vec3(0.0)))) discard;
    } else {
        cover = clamp(u_width_px * 0.5 - abs(across) + 0.5, 0.0, 1.0);
        if (!tested && !spine_visible(spine, line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) discard;
    }
    cover *= clamp(0.5 - outside_ends, 0.0, 1.0);
    if (cover <= 0.0) discard;
    o_color = vec4(mix(vec3(1.0), u_ink, cover), 1.0);  // MIN blended onto the fill
}

// The hidden stroke at a fragment whose spine point is hidden: its coverage (0: none) and ink.
float hidden_cover(vec2 p, int level, out vec3 ink) {
    vec2 d = g_p1 - g_p0;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    float along = dot(p - g_p0, dir);
    float across = dot(p - g_p0, vec2(-dir.y, dir.x));
    float width = u_width_px * u_hidden_width_scale;
    float cover = clamp(width * 0.5 - abs(across) + 0.5, 0.0, 1.0);
    cover *= clamp(0.5 - max(-along, along - len), 0.0, 1.0);
    // Dashes measured along the edge from its first end, antialiased at their ends: the
    // pattern is fixed to the edge, not to the screen, so it does not crawl.
    float period = u_dash_px + u_gap_px;
    if (u_gap_px > 0.0 && period > 0.0) {
        float m = mod(along, period);
        float in_dash = clamp(min(m + 0.5, u_dash_px - m + 0.5), 0.0, 1.0);
        float wrapped = clamp(m - period + 0.5, 0.0, 1.0);  // the next dash's start
        cover *= max(in_dash, wrapped);
    }
    // Deeper levels fade towards the paper: level 1 at the ink, level 3 halfway (as the SVG).
    ink = mix(u_ink, vec3(1.0), 0.25 * float(level - 1));
    return cover;
}

// The spine point's occlusion level when it is to be drawn hidden, else 0.
int drawn_hidden_level(vec2 spine, float line_inv) {
    if (u_hidden_levels == 0) return 0;
    int level = max(occlusion_level(spine, line_inv,
                                    EdgeFaces(g_edge_plane, g_face_pos, g_face_neg), g_nudge), 1);
    return level <= u_hidden_levels ? level : 0;
}

void main() {
#ifdef MASK_MODE
    vec2 p = gl_FragCoord.xy;
    if (!crosses_pixel(p, g_p0, g_p1)) discard;
    float t = closest_t(p, g_p0, g_p1);
    vec2 spine = mix(g_p0, g_p1, t);
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, t);
    int level = 0;
    if (!spine_visible(spine, line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) {
        level = drawn_hidden_level(spine, line_inv);
        if (level == 0) discard;
    }
    o_color = vec4(float(255 - 64 * level) / 255.0);
#else
    if (u_hidden_levels == 0 || (u_one_sided && g_kind == KIND_SILHOUETTE)) {
        visible_stroke(false);
        return;
    }
    vec2 p = g_pixel;
    float t = closest_t(p, g_p0, g_p1);
    vec2 spine = mix(g_p0, g_p1, t);
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, t);
    if (spine_visible(spine, line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) {
        visible_stroke(true);
        return;
    }
    int level = drawn_hidden_level(spine, line_inv);
    if (level == 0) discard;
    vec3 ink;
    float cover = hidden_cover(p, level, ink);
    if (cover <= 0.0) discard;
    o_color = vec4(mix(vec3(1.0), ink, cover), 1.0);
#endif
}
