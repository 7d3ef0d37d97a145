// The glow's share of phosphor persistence (GLOW_PHOSPHOR; pass_bloom.cpp): the finished bloom
// is the brighter, per channel, of this frame's and last frame's decayed by this step of the
// phosphor, so the glow of a moving line trails and fades with its picture instead of
// vanishing. (Blooming the phosphor picture itself would need the picture before the bloom,
// a second full-resolution pass on llvmpipe; the glow is this frame's blur of light that
// decays the same way, so both fade alike.)
// It works on the encoded bloom (bloom_encoding.glsl, sqrt of linear): light decayed by f is
// the encoded value times sqrt(f). Each step also takes at least one 8-bit step off, so that
// a faint glow reaches exact black instead of rounding back to itself.
#ifdef GLOW_PHOSPHOR
layout(binding = TEXTURE_UNIT_GLOW_LAST) uniform sampler2D u_glow_last;     // last frame's finished bloom, encoded
uniform float u_glow_sqrt_factor;  // sqrt of this step's decay of the phosphor (0 at a reset)

vec3 persist_glow(vec3 encoded) {
    vec3 last = texelFetch(u_glow_last, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 held = max(min(last * u_glow_sqrt_factor, last - 1.0 / 255.0), 0.0);
    return max(encoded, held);
}
#else
vec3 persist_glow(vec3 encoded) { return encoded; }
#endif
