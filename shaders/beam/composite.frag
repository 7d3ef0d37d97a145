#version 450 core
// Lines plus scaled bloom, tone-mapped on the brightest channel (so a dense green tangle stays
// green instead of washing out to white), then gamma-encoded for the screen.
// This runs once per screen pixel, and on llvmpipe every transcendental call there costs a
// polynomial per channel: the tone map uses one exp2 per pixel, and the gamma curve is a fit
// made of two square roots (native instructions) instead of pow().
// It draws either one full-screen triangle or, sparse, one quad per lit screen tile
// (lit_tiles.vert, from tile_list.comp's list); positions come from gl_FragCoord so both give the same pixels.
// With PHOSPHOR it also advances the phosphor: u_lines is this frame's beam image, the
// picture is max(beam, decayed history) (phosphor.glsl), updated in place for the next frame.
#include "bloom_encoding.glsl"
#ifdef PHOSPHOR
#include "lit_tiles.glsl"
#include "phosphor.glsl"
// The picture, last frame's on entry. Each invocation reads and writes only its own pixel's
// texel (one fragment per pixel), so in place is free of hazards.
layout(rgba16f, binding = IMAGE_UNIT_PICTURE) uniform image2D u_picture;
// Per lit tile (lit_tiles.glsl): the new picture holds light there (cleared before; the next
// frame's tile_list.comp reads it).
layout(r8ui, binding = IMAGE_UNIT_PICTURE_LIT) uniform writeonly uimage2D u_picture_lit;
#endif

layout(binding = TEXTURE_UNIT_LINES) uniform sampler2D u_lines;
layout(binding = TEXTURE_UNIT_BLOOM) uniform sampler2D u_bloom;  // encoded 8-bit (bloom_encoding.glsl)
uniform float u_bloom_strength;
uniform float u_exposure;
uniform bool u_overlay;  // Battlezone's cabinet overlay over a white tube
uniform bool u_overlay_safe;  // its red film as violet-blue: apart from green for red-green blindness
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
    vec3 top = u_overlay_safe ? vec3(0.6, 0.125, 1.0) : vec3(1.0, 0.125, 0.125);
    return white * (uv.y > 0.8 ? top : vec3(0.125, 1.0, 0.125));
}

void main() {
    vec2 uv = gl_FragCoord.xy * u_inv_screen;
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 hdr = texelFetch(u_lines, px, 0).rgb;
#ifdef PHOSPHOR
    vec4 history = imageLoad(u_picture, px);
    vec4 picture = phosphor_picture(hdr, history);
    // A still dark pixel, or a still line, stores nothing.
    if (picture != history) imageStore(u_picture, px, picture);
    if (phosphor_peak(picture.rgb) > 0.0) imageStore(u_picture_lit, px / kLitTile, uvec4(1u));
    hdr = picture.rgb;
#endif
    if (u_bloom_strength > 0.0) hdr += decode_bloom(texture(u_bloom, uv).rgb) * u_bloom_strength;
    hdr *= u_exposure;
    if (u_overlay) hdr = overlay(hdr, uv);
    float peak = max(max(hdr.r, hdr.g), max(hdr.b, 1e-6));
    // 1 - exp(-peak), written with exp2 so that it is one scalar call.
    vec3 mapped = hdr * ((1.0 - exp2(-1.44269504 * peak)) / peak);
    o_color = vec4(encode_gamma(mapped), 1.0);
}
