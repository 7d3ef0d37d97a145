#version 450 core
// Box-filtered downsample into the bloom resolution (or the next level of the bloom chain).
// Bilinear fetches at texel corners average 2x2 texels each; `u_factor` (1, 2 or 4) picks how
// many. With a threshold, only light above it glows (soft knee), so dim lines - a far floor
// grating - stay lines on black instead of a haze.
// The first level is drawn over the whole target or, sparse, over the screen tiles the beam
// lit (composite_tiles.vert over beam_tiles.glsl's marks; pass_bloom.cpp): a block reads only
// its own texels, so every other block is exactly black, which a clear writes for free.
// Positions come from gl_FragCoord, so both give the same texels.
// The first level also marks the screen tile under each block of the beam image that holds
// any light (lit_tiles.glsl; a filtered sum of non-negative texels is zero only if all are),
// so that the sparse composite shades it even where the light stays under the threshold.
#include "lit_tiles.glsl"

layout(binding = TEXTURE_UNIT_SOURCE) uniform sampler2D u_source;
uniform int u_factor;
uniform vec2 u_inv_target;  // 1 / this target's size in texels
uniform float u_threshold;  // peak-channel brightness where glow starts (0: everything glows)
uniform float u_knee;       // half-width of the soft knee around the threshold
layout(location = 0) out vec4 o_color;

vec3 box(vec2 uv) {
    if (u_factor == 1) return texture(u_source, uv).rgb;
    if (u_factor == 2) return texture(u_source, uv).rgb;  // centre of a 2x2 block: one fetch
    vec2 texel = 1.0 / vec2(textureSize(u_source, 0));
    vec3 sum = texture(u_source, uv + texel * vec2(-1.0, -1.0)).rgb +
               texture(u_source, uv + texel * vec2(1.0, -1.0)).rgb +
               texture(u_source, uv + texel * vec2(-1.0, 1.0)).rgb +
               texture(u_source, uv + texel * vec2(1.0, 1.0)).rgb;
    return sum * 0.25;
}

// Keeps what lies above the threshold; quadratic across [threshold - knee, threshold + knee]
// so that glow fades in without an edge. Scales the colour, keeping its hue.
vec3 above_threshold(vec3 c) {
    float peak = max(c.r, max(c.g, c.b));
    float soft = clamp(peak - u_threshold + u_knee, 0.0, 2.0 * u_knee);
    soft = soft * soft / (4.0 * u_knee + 1e-6);
    float kept = max(soft, peak - u_threshold);
    return c * (kept / max(peak, 1e-6));
}

void main() {
    vec3 c = box(gl_FragCoord.xy * u_inv_target);
#ifdef LIT_TILES
    if (max(c.r, max(c.g, c.b)) > 0.0) {
        ivec2 block = ivec2(gl_FragCoord.xy) * u_factor;
        mark_pixels(block, block);
    }
#endif
    o_color = vec4(u_threshold > 0.0 ? above_threshold(c) : c, 1.0);
}
