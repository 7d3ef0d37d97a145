#version 450 core
// LineMethod::compute's line fragments (edge_quad.vert draws the quads): the beam profile,
// with visibility looked up from the spine samples that spine_visibility.comp tested, or -
// for a record that got no samples - the spine test itself, from the record's planes. With
// MASK_MODE it marks each pixel its visible spine crosses (the accuracy mask).
//
// Few varyings on purpose: llvmpipe sets every varying up per triangle on its one setup
// thread, and the spine test's planes alone are 11 floats that most quads never read. A quad
// that needs them reads its record instead.
#include "edge_record.glsl"
#include "../beam/beam.glsl"
#include "spine_samples.glsl"
#include "spine_test.glsl"

layout(std430, binding = EDGE_RECORDS_BINDING) readonly buffer Records { EdgeRecord records[]; };
layout(std430, binding = SPINE_SAMPLES_BINDING) readonly buffer Samples { uint spine_samples[]; };

uniform mat4 u_proj;
uniform vec2 u_viewport;
uniform float u_near;
uniform float u_far;
#include "edge_geometry.glsl"
#include "record_spine_test.glsl"

#ifdef MASK_MODE
flat in vec4 g_ends;     // spine end points, window pixels
#else
noperspective in vec4 g_line;  // x: t along the spine (unclamped), y: px across it, z: px
                               // along it from the start, w: px along it from the end
#endif
flat in vec4 g_shade;    // rgb: colour times the beam's gain; w: half-width (px)
flat in vec4 g_stretch;  // xy: the visible stretch (t); z: beam softness; w: samples stored when
                         // they must be looked up, 0 when the whole stretch is visible
flat in uvec4 g_samples; // x: first stored sample, y: samples (0: none, test here), z: first
                         // sampled index, w: the record

layout(location = 0) out vec4 o_color;

#ifdef MASK_MODE
#include "pixel_cross.glsl"
#endif
#ifdef OCCLUSION_LEVELS
// vector-xray: each surface facing the eye in front of the line dims it (StyleDef::hidden).
#include "occlusion_level.glsl"
uniform float u_level_dim;

float level_brightness(float t) {
    EdgeRecord r = records[g_samples.w];
    vec2 spine = mix(r.screen.xy, r.screen.zw, t);
    float line_inv = mix(r.depth.x, r.depth.y, t);
    EdgeFaces faces = EdgeFaces(r.edge_plane.xyz, r.face_pos.xyz, r.face_neg.xyz);
    return pow(u_level_dim, float(occlusion_level(spine, line_inv, faces, record_nudge(r))));
}
#endif

#ifndef SPINE_SAMPLES_ONLY
// The spine test of a record that got no samples (the sample buffer was full, or the frame
// takes none).
bool tested_here(float t) {
    EdgeRecord r = records[g_samples.w];
    return record_spine_visible(r, t, record_nudge(r));
}
#endif

// Whether the spine point at parameter t is visible. SPINE_SAMPLES_ONLY: the program of the
// draw whose records all have samples leaves the test out: llvmpipe runs both sides of a
// branch for every fragment, and the test's code alone, never taken, cost 5 of the 12 ms
// of the seed's hallway's quads (pass_edge_quads.cpp).
bool spine_point_visible(float t) {
#ifndef SPINE_SAMPLES_ONLY
    if (g_samples.y == 0u) return tested_here(t);
#endif
    if (t < g_stretch.x || t >= g_stretch.y) return false;
    if (g_stretch.w == 0.0) return true;  // no hidden sample inside the stretch
    uint k = clamp(spine_sample_index(t, g_samples.y), g_samples.z, g_samples.z + uint(g_stretch.w) - 1u);
    return spine_samples[g_samples.x + (k - g_samples.z)] != 0u;
}

void main() {
#ifdef MASK_MODE
    vec2 p0 = g_ends.xy, p1 = g_ends.zw;
    vec2 p = gl_FragCoord.xy;
    float t = closest_t(p, p0, p1);
    if (!crosses_pixel(p, p0, p1)) discard;
    if (!spine_point_visible(t)) discard;
    o_color = vec4(1.0);
#else
    float t = clamp(g_line.x, 0.0, 1.0);
    // Past an end, the distance along the spine beyond it, less the lengthening
    // (beam_ends.glsl): the distance to the lengthened spine, as beam_distance measures it.
    float e = beam_end_lengthening(g_shade.w);
    float beyond = min(g_line.z + e, 0.0) + max(g_line.w - e, 0.0);
    float dist = length(vec2(g_line.y, beyond));
    if (dist >= g_shade.w) discard;
    if (!spine_point_visible(t)) discard;
    o_color = vec4(g_shade.rgb * beam_profile(dist, g_shade.w, g_stretch.z), 1.0);
#ifdef OCCLUSION_LEVELS
    o_color.rgb *= level_brightness(t);
#endif
#endif
}
