#version 450 core
// One direction of a separable Gaussian with linear sampling (Rakos): each fetch between two
// texels returns their weighted sum through the bilinear filter, halving the fetch count.
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_direction;  // (1,0) or (0,1)
uniform int u_fetches;     // centre + pairs on each side
uniform float u_offsets[16];
uniform float u_weights[16];
layout(location = 0) out vec4 o_color;

void main() {
    vec2 step_uv = u_direction / vec2(textureSize(u_source, 0));
    vec4 sum = texture(u_source, v_uv) * u_weights[0];
    for (int i = 1; i < u_fetches; ++i) {
        vec2 off = step_uv * u_offsets[i];
        sum += (texture(u_source, v_uv + off) + texture(u_source, v_uv - off)) * u_weights[i];
    }
    o_color = sum;
}
