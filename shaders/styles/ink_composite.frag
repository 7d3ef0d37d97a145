#version 450 core
// Filled styles: the canvas (paper, fills, ink) is already display-referred; the HUD lines
// (HDR, from the lines target) go on top, tone-mapped like the vector composite and laid over
// the paper by their own strength, so green radar and score stay readable on light paper.
in vec2 v_uv;
uniform sampler2D u_canvas;
uniform sampler2D u_lines;
layout(location = 0) out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 paper = texelFetch(u_canvas, p, 0).rgb;
    vec3 hud = texelFetch(u_lines, p, 0).rgb;
    float peak = max(max(hud.r, hud.g), hud.b);
    float a = 1.0 - exp(-peak);
    vec3 hud_colour = peak > 1e-6 ? pow(hud / peak, vec3(1.0 / 2.2)) * 0.8 : vec3(0.0);
    o_color = vec4(mix(paper, hud_colour, a), 1.0);
}
