#version 450 core
// Shades one feature-line quad: spine test against the prepass depth, then the beam profile.
// With MASK_MODE it instead marks each pixel its visible spine crosses (the accuracy mask).
#include "../beam/beam.glsl"
#include "spine_test.glsl"

noperspective in vec2 g_pixel;
flat in vec2 g_p0;
flat in vec2 g_p1;
flat in vec2 g_inv_depth;
flat in vec3 g_edge_plane;
flat in vec3 g_face_pos;
flat in vec3 g_face_neg;
flat in vec2 g_nudge;
flat in vec3 g_color;
flat in vec3 g_beam;  // half-width (px), gain, softness (beam_width.glsl)

layout(location = 0) out vec4 o_color;

#ifdef MASK_MODE
#include "pixel_cross.glsl"
#endif
#ifdef OCCLUSION_LEVELS
// vector-xray: each surface facing the eye in front of the line dims it (StyleDef::hidden).
#include "occlusion_level.glsl"
uniform float u_level_dim;
#endif

void main() {
    vec2 p = gl_FragCoord.xy;
#ifndef MASK_MODE
    p = g_pixel;
#endif
    float t = closest_t(p, g_p0, g_p1);
    vec2 spine = mix(g_p0, g_p1, t);
    float line_inv = mix(g_inv_depth.x, g_inv_depth.y, t);  // 1/depth is affine on screen
#ifdef MASK_MODE
    if (!crosses_pixel(p, g_p0, g_p1)) discard;
    if (!spine_visible(spine, line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) discard;
    o_color = vec4(1.0);
#else
    float dist = beam_distance(p, g_p0, g_p1, spine, g_beam.x);  // lengthened ends: beam_ends.glsl
    if (dist >= g_beam.x) discard;
    if (!spine_visible(spine, line_inv, g_edge_plane, g_face_pos, g_face_neg, g_nudge)) discard;
    o_color = vec4(g_color * (g_beam.y * beam_profile(dist, g_beam.x, g_beam.z)), 1.0);
#ifdef OCCLUSION_LEVELS
    EdgeFaces faces = EdgeFaces(g_edge_plane, g_face_pos, g_face_neg);
    o_color.rgb *= pow(u_level_dim, float(occlusion_level(spine, line_inv, faces, g_nudge)));
#endif
#endif
}
