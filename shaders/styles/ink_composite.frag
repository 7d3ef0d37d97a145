#version 450 core
// Filled styles: the canvas (paper, fills, ink) is already display-referred; the HUD lines
// (HDR, from the lines target) go on top by their own strength.
// With the style's ink HUD theme (scene::HudTheme) each HUD line is drawn as ink in its own
// hue, darkened to at most u_ink_luminance (relative luminance), over a paper-toned halo
// HudTheme::halo_px wide: text and notices then keep their contrast on light paper and over
// the fills and strokes behind them. Without it, the HUD's tone-mapped colour goes over the paper.
in vec2 v_uv;
layout(binding = TEXTURE_UNIT_CANVAS) uniform sampler2D u_canvas;
layout(binding = TEXTURE_UNIT_LINES) uniform sampler2D u_lines;
uniform bool u_ink;
uniform float u_ink_luminance;
uniform vec3 u_paper;  // display-referred paper tone, the halo's colour
layout(location = 0) out vec4 o_color;

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 paper = texelFetch(u_canvas, p, 0).rgb;
    vec4 lines = texelFetch(u_lines, p, 0);
    vec3 hud = lines.rgb;
    float peak = max(max(hud.r, hud.g), hud.b);
    float a = 1.0 - exp(-peak);
    if (!u_ink) {
        vec3 hud_colour = peak > 1e-6 ? pow(hud / peak, vec3(1.0 / 2.2)) * 0.8 : vec3(0.0);
        o_color = vec4(mix(paper, hud_colour, a), 1.0);
        return;
    }
    // The paper halo: the HUD pass wrote each line's coverage halo_px out, dilated, into
    // alpha (shaders/hud/hud.frag). Sixteen bilinear taps of this image here cost ~3 of the
    // composite's ~5 ms at 1280x720 on llvmpipe (docs/measurements/styles-sweep.md).
    float halo = lines.a;
    vec3 under = mix(paper, u_paper, max(halo, a));
    vec3 hue = peak > 1e-6 ? hud / peak : vec3(0.0);
    float lum = dot(hue, kLuminance);
    vec3 ink = hue * min(1.0, u_ink_luminance / max(lum, 1e-4));
    // Ink covers fully from a little coverage on: thin text stays dark, not a faint tint.
    float ink_a = min(1.0, 4.0 * a);
    o_color = vec4(mix(under, pow(ink, vec3(1.0 / 2.2)), ink_a), 1.0);
}
