#version 450 core
// Toon and pop-art outlines (Castro & Macedo): solid ink over the fill. Centred quads keep a
// fragment when the spine test passes at its nearest spine point; one-sided silhouette quads
// lie outside the object and are tested against the depth at the fragment itself (Castro &
// Macedo's "extruded outward, depth-tested"). Edges are antialiased over one pixel.
#include "../beam/beam.glsl"
#include "../lines/spine_test.glsl"
#include "stroke_varyings.glsl"

uniform float u_width_px;
uniform float u_overdraw;
uniform bool u_one_sided;
uniform vec3 u_ink;

layout(location = 0) out vec4 o_color;

void main() {
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
        if (!spine_visible(spine, line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) discard;
    }
    cover *= clamp(0.5 - outside_ends, 0.0, 1.0);
    if (cover <= 0.0) discard;
    o_color = vec4(mix(vec3(1.0), u_ink, cover), 1.0);  // MIN blended onto the fill
}
