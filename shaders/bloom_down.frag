#version 450 core
// Box-filtered downsample of the line target into the bloom resolution. Bilinear fetches at
// texel corners average 2x2 texels each; `u_factor` (1, 2 or 4) picks how many.
in vec2 v_uv;
uniform sampler2D u_source;
uniform int u_factor;
layout(location = 0) out vec4 o_color;

void main() {
    if (u_factor == 1) {
        o_color = texture(u_source, v_uv);
        return;
    }
    vec2 texel = 1.0 / vec2(textureSize(u_source, 0));
    if (u_factor == 2) {
        o_color = texture(u_source, v_uv);  // centre of a 2x2 block: one bilinear fetch
        return;
    }
    vec4 sum = texture(u_source, v_uv + texel * vec2(-1.0, -1.0)) +
               texture(u_source, v_uv + texel * vec2(1.0, -1.0)) +
               texture(u_source, v_uv + texel * vec2(-1.0, 1.0)) +
               texture(u_source, v_uv + texel * vec2(1.0, 1.0));
    o_color = sum * 0.25;
}
