#version 450 core
// Lines plus scaled bloom, tone-mapped on the brightest channel (so a dense green tangle stays
// green instead of washing out to white), then gamma-encoded for the screen.
in vec2 v_uv;
uniform sampler2D u_lines;
uniform sampler2D u_bloom;
uniform float u_bloom_strength;
uniform float u_exposure;
layout(location = 0) out vec4 o_color;

void main() {
    vec3 hdr = texelFetch(u_lines, ivec2(gl_FragCoord.xy), 0).rgb + texture(u_bloom, v_uv).rgb * u_bloom_strength;
    hdr *= u_exposure;
    float peak = max(max(hdr.r, hdr.g), hdr.b);
    vec3 mapped = peak > 1e-6 ? hdr * ((1.0 - exp(-peak)) / peak) : vec3(0.0);
    o_color = vec4(pow(mapped, vec3(1.0 / 2.2)), 1.0);
}
