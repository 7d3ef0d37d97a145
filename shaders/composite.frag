#version 450 core
// Lines plus scaled bloom, tone-mapped on the brightest channel (so a dense green tangle stays
// green instead of washing out to white), then gamma-encoded for the screen.
// This runs once per screen pixel, and on llvmpipe every transcendental call there costs a
// polynomial per channel: the tone map uses one exp2 per pixel, and the gamma curve is a fit
// made of two square roots (native instructions) instead of pow().
// It draws either one full-screen triangle or, sparse, one quad per lit screen tile
// (composite_tiles.vert); positions come from gl_FragCoord so both give the same pixels.
#include "bloom_encoding.glsl"

uniform sampler2D u_lines;
uniform sampler2D u_bloom;  // encoded 8-bit (bloom_encoding.glsl)
uniform float u_bloom_strength;
uniform float u_exposure;
uniform bool u_overlay;  // Battlezone's cabinet overlay over a white tube
uniform vec2 u_inv_screen;  // 1 / target size in pixels
layout(location = 0) out vec4 o_color;

// x^(1/2.2) on [0, 1] as a s + b sqrt(s) + c x with s = sqrt(x): a least-squares minimax fit,
// off by at most 0.49 of an 8-bit step (the exact curve rounds to the same byte or the next).
vec3 encode_gamma(vec3 x) {
    vec3 s = sqrt(x);
    return 1.00788282 * s + 0.06986666 * sqrt(s) - 0.07965437 * x;
}

// The cabinet's overlay (as MAME's Battlezone layout has it): the tube is white, the top
// fifth of the screen is seen through red film, the rest through green.
vec3 overlay(vec3 hdr, vec2 uv) {
    float white = max(hdr.r, max(hdr.g, hdr.b));
    return white * (uv.y > 0.8 ? vec3(1.0, 0.125, 0.125) : vec3(0.125, 1.0, 0.125));
}

void main() {
    vec2 uv = gl_FragCoord.xy * u_inv_screen;
    vec3 hdr = texelFetch(u_lines, ivec2(gl_FragCoord.xy), 0).rgb;
    if (u_bloom_strength > 0.0) hdr += decode_bloom(texture(u_bloom, uv).rgb) * u_bloom_strength;
    hdr *= u_exposure;
    if (u_overlay) hdr = overlay(hdr, uv);
    float peak = max(max(hdr.r, hdr.g), max(hdr.b, 1e-6));
    // 1 - exp(-peak), written with exp2 so that it is one scalar call.
    vec3 mapped = hdr * ((1.0 - exp2(-1.44269504 * peak)) / peak);
    o_color = vec4(encode_gamma(mapped), 1.0);
}
