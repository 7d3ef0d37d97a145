#version 450 core
// One direction of a separable Gaussian with linear sampling (Rakos): each fetch between two
// texels returns their weighted sum through the bilinear filter, halving the fetch count.
// The kernel arrives as compile-time constants (BLOOM_FETCHES, BLOOM_OFFSETS, BLOOM_WEIGHTS):
// on llvmpipe a loop over uniform arrays costs three times as much as the unrolled constants.
// The last direction writes the encoded 8-bit image the composite reads (u_encode) and marks
// the screen tiles its light reaches (LIT_TILES).
#include "bloom_encoding.glsl"
#include "glow_persistence.glsl"
#include "lit_tiles.glsl"

in vec2 v_uv;
layout(binding = TEXTURE_UNIT_SOURCE) uniform sampler2D u_source;
uniform vec2 u_direction;  // (1,0) or (0,1)
uniform bool u_encode;
uniform float u_floor;  // black level taken off the finished bloom (only when u_encode)
uniform int u_factor;   // screen pixels per bloom texel (marks, only when u_encode)
layout(location = 0) out vec4 o_color;

const float kOffsets[BLOOM_FETCHES] = BLOOM_OFFSETS;
const float kWeights[BLOOM_FETCHES] = BLOOM_WEIGHTS;

void main() {
    vec2 step_uv = u_direction / vec2(textureSize(u_source, 0));
    vec4 sum = texture(u_source, v_uv) * kWeights[0];
    for (int i = 1; i < BLOOM_FETCHES; ++i) {
        vec2 off = step_uv * kOffsets[i];
        sum += (texture(u_source, v_uv + off) + texture(u_source, v_uv - off)) * kWeights[i];
    }
    if (!u_encode) {
        o_color = sum;
        return;
    }
    vec3 bloom = persist_glow(encode_bloom(max(sum.rgb - u_floor, 0.0)));
#ifdef LIT_TILES
    // The finished bloom marks the tiles its light reaches (lit_tiles.glsl).
    if (stores_light(bloom)) mark_bloom_texel(ivec2(gl_FragCoord.xy), u_factor);
#endif
    o_color = vec4(bloom, 1.0);
}
