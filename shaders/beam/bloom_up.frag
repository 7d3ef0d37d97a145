#version 450 core
// One step up the bloom chain (pass_bloom_mips.cpp). Level k holds, once its step is done,
// S_k = L_k + (w_{k+1} / w_k) * upsample(S_{k+1}), so that w_0 * S_0 is the weighted sum of
// every level. A step is drawn with additive blending into level k (u_final = false), or, for
// level 0, written as the finished, 8-bit encoded bloom (u_final = true), which marks the
// screen tiles its light reaches (LIT_TILES).
#include "bloom_encoding.glsl"
#include "glow_persistence.glsl"
#include "lit_tiles.glsl"

in vec2 v_uv;
layout(binding = TEXTURE_UNIT_COARSER) uniform sampler2D u_coarser;  // S_{k+1}
layout(binding = TEXTURE_UNIT_LEVEL) uniform sampler2D u_level;    // L_k (only read when u_final)
uniform float u_ratio;        // w_{k+1} / w_k
uniform float u_weight;       // w_0 / sum of weights (only when u_final)
uniform bool u_final;
uniform float u_floor;        // black level taken off the finished bloom (only when u_final)
uniform int u_factor;         // screen pixels per level-0 texel (marks, only when u_final)
layout(location = 0) out vec4 o_color;

void main() {
    vec3 up = texture(u_coarser, v_uv).rgb * u_ratio;
    if (!u_final) {
        o_color = vec4(up, 1.0);
        return;
    }
    vec3 level = texelFetch(u_level, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 bloom = persist_glow(encode_bloom(max((level + up) * u_weight - u_floor, 0.0)));
#ifdef LIT_TILES
    // The finished bloom marks the tiles its light reaches (lit_tiles.glsl).
    if (stores_light(bloom)) mark_bloom_texel(ivec2(gl_FragCoord.xy), u_factor);
#endif
    o_color = vec4(bloom, 1.0);
}
